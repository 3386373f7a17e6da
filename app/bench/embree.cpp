// Intel Embree 3 as the reference, in the benchmark only (RTVIEW_WITH_EMBREE).
#include "app/bench/bench.h"

#ifdef RTVIEW_HAVE_EMBREE
#include <embree3/rtcore.h>

#include "core/simd.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace rt::bench {
namespace {

class Embree : public Structure {
  public:
    // `robust`: RTC_SCENE_FLAG_ROBUST, Embree's watertight triangle test (Pluecker) and
    // conservative box test: the guarantees our own structures always give.
    explicit Embree(int threads, bool robust = false) : robust_(robust) {
        std::string config = "threads=" + std::to_string(threads);
        if (const char* extra = std::getenv("RTBENCH_EMBREE_CONFIG"))
            config += std::string(",") + extra;
        device_ = rtcNewDevice(config.c_str());
        if (!device_) throw std::runtime_error("rtcNewDevice failed");
        // Counts what Embree allocates, to report its memory like ours.
        rtcSetDeviceMemoryMonitorFunction(
            device_,
            [](void* user, ssize_t bytes, bool) {
                static_cast<std::atomic<long long>*>(user)->fetch_add(bytes);
                return true;
            },
            &bytes_);
    }
    ~Embree() override {
        if (scene_) rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }
    std::string name() const override { return robust_ ? "embree-robust" : "embree"; }

    void prepare(const rt::TriangleMesh& mesh) override {
        if (scene_) rtcReleaseScene(scene_);
        scene_ = rtcNewScene(device_);
        if (robust_) rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    3 * sizeof(float), mesh.positions.size()));
        std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * sizeof(rt::vec3));
        auto* indices = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), mesh.triangles.size()));
        std::memcpy(indices, mesh.triangles.data(), mesh.triangles.size() * sizeof(glm::uvec3));
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
        bytes_before_build_ = bytes_.load();
    }
    void build() override { rtcCommitScene(scene_); }
    std::size_t memory_bytes() const override {
        return static_cast<std::size_t>(std::max(0LL, bytes_.load() - bytes_before_build_));
    }

    Result intersect(const rt::Ray& ray, float t_max) const override {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        set_ray(rh.ray, ray, t_max);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
        return {rh.ray.tfar, rh.hit.primID};
    }
    bool occluded(const rt::Ray& ray, float t_max) const override {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay r{};
        set_ray(r, ray, t_max);
        rtcOccluded1(scene_, &context, &r);
        return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
    }

  protected:
    static void set_ray(RTCRay& r, const rt::Ray& ray, float t_max) {
        r.org_x = ray.origin.x;
        r.org_y = ray.origin.y;
        r.org_z = ray.origin.z;
        r.dir_x = ray.dir.x;
        r.dir_y = ray.dir.y;
        r.dir_z = ray.dir.z;
        r.tnear = 0.0f;
        r.tfar = t_max;
        r.mask = ~0u;
        r.flags = 0;
    }

    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::atomic<long long> bytes_{0};
    long long bytes_before_build_ = 0;
    bool robust_ = false;
};

// The same scene, the rays handed over kPacketWidth at a time: rtcIntersect8 /
// rtcOccluded8 (rtcIntersect4 / rtcOccluded4 where our packets are 4 wide, rtcIntersect16 /
// rtcOccluded16 where a build makes them 16 wide: core/simd.h).
class EmbreePackets : public Embree {
  public:
    using Embree::Embree;
    std::string name() const override { return "embree-packets"; }
    bool packets() const override { return true; }

    static_assert(rt::kPacketWidth == 4 || rt::kPacketWidth == 8 || rt::kPacketWidth == 16);
    using RayHitN =
        std::conditional_t<rt::kPacketWidth == 16, RTCRayHit16,
                           std::conditional_t<rt::kPacketWidth == 8, RTCRayHit8, RTCRayHit4>>;
    using RayN = std::conditional_t<rt::kPacketWidth == 16, RTCRay16,
                                    std::conditional_t<rt::kPacketWidth == 8, RTCRay8, RTCRay4>>;
    void intersect_packet(const rt::Ray* rays, const float* t_max, int count,
                          Result* out) const override {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        alignas(64) int valid[rt::kPacketWidth];
        alignas(64) RayHitN rh{};
        fill(rh.ray, rays, t_max, count, valid);
        for (int i = 0; i < rt::kPacketWidth; ++i) rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        intersect_n(valid, &context, &rh);
        for (int i = 0; i < count; ++i)
            out[i] = rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID
                         ? Result{}
                         : Result{rh.ray.tfar[i], rh.hit.primID[i]};
    }
    void occluded_packet(const rt::Ray* rays, const float* t_max, int count,
                         Result* out) const override {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        alignas(64) int valid[rt::kPacketWidth];
        alignas(64) RayN r{};
        fill(r, rays, t_max, count, valid);
        occluded_n(valid, &context, &r);
        for (int i = 0; i < count; ++i) out[i].t = r.tfar[i] < 0.0f ? 0.0f : rt::kInfinity;
    }

  private:
    void intersect_n(const int* valid, RTCIntersectContext* c, RTCRayHit8* rh) const {
        rtcIntersect8(valid, scene_, c, rh);
    }
    void intersect_n(const int* valid, RTCIntersectContext* c, RTCRayHit4* rh) const {
        rtcIntersect4(valid, scene_, c, rh);
    }
    void intersect_n(const int* valid, RTCIntersectContext* c, RTCRayHit16* rh) const {
        rtcIntersect16(valid, scene_, c, rh);
    }
    void occluded_n(const int* valid, RTCIntersectContext* c, RTCRay8* r) const {
        rtcOccluded8(valid, scene_, c, r);
    }
    void occluded_n(const int* valid, RTCIntersectContext* c, RTCRay4* r) const {
        rtcOccluded4(valid, scene_, c, r);
    }
    void occluded_n(const int* valid, RTCIntersectContext* c, RTCRay16* r) const {
        rtcOccluded16(valid, scene_, c, r);
    }
    static void fill(RayN& r, const rt::Ray* rays, const float* t_max, int count, int* valid) {
        for (int i = 0; i < rt::kPacketWidth; ++i) {
            valid[i] = i < count ? -1 : 0;
            const rt::Ray& ray = rays[std::min(i, count - 1)];
            r.org_x[i] = ray.origin.x;
            r.org_y[i] = ray.origin.y;
            r.org_z[i] = ray.origin.z;
            r.dir_x[i] = ray.dir.x;
            r.dir_y[i] = ray.dir.y;
            r.dir_z[i] = ray.dir.z;
            r.tnear[i] = 0.0f;
            r.tfar[i] = t_max[std::min(i, count - 1)];
            r.mask[i] = ~0u;
            r.flags[i] = 0;
        }
    }
};

}  // namespace

std::unique_ptr<Structure> make_embree(int threads, bool packets) {
    if (packets) return std::make_unique<EmbreePackets>(threads);
    return std::make_unique<Embree>(threads);
}
std::unique_ptr<Structure> make_embree_robust(int threads) {
    return std::make_unique<Embree>(threads, true);
}
bool have_embree() { return true; }

}  // namespace rt::bench

#else

namespace rt::bench {
std::unique_ptr<Structure> make_embree(int, bool) { return nullptr; }
std::unique_ptr<Structure> make_embree_robust(int) { return nullptr; }
bool have_embree() { return false; }
}  // namespace rt::bench

#endif
