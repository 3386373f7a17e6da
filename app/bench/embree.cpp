// Intel Embree 3 as the reference, in the benchmark only (RTVIEW_WITH_EMBREE).
#include "app/bench/bench.h"

#ifdef RTVIEW_HAVE_EMBREE
#include <embree3/rtcore.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace rt::bench {
namespace {

class Embree : public Structure {
  public:
    explicit Embree(int threads) {
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
    std::string name() const override { return "embree"; }

    void prepare(const rt::TriangleMesh& mesh) override {
        if (scene_) rtcReleaseScene(scene_);
        scene_ = rtcNewScene(device_);
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

  private:
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
};

}  // namespace

std::unique_ptr<Structure> make_embree(int threads) { return std::make_unique<Embree>(threads); }
bool have_embree() { return true; }

}  // namespace rt::bench

#else

namespace rt::bench {
std::unique_ptr<Structure> make_embree(int) { return nullptr; }
bool have_embree() { return false; }
}  // namespace rt::bench

#endif
