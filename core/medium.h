#pragma once
// Which refractive objects a ray is inside: a small stack, innermost last (POV-Ray's
// "interior list"). Refraction decides entering or leaving from it, never from the way a
// surface is wound, so glass meshes wound inward, mirrored by a negative scale, or glass
// inside glass refract the same as glass wound outward. The camera is in air.

#include <array>
#include <cstdint>

namespace rt {

class MediumStack {
  public:
    static constexpr int kCapacity = 8;

    // The index of refraction the ray travels in: the innermost object's, or air's.
    float ior() const { return size_ == 0 ? 1.0f : media_[size_ - 1].ior; }
    int size() const { return size_; }
    bool empty() const { return size_ == 0; }

    // What crossing a surface of `object` (its material's index `object_ior` there) does:
    // the indices on both sides, and the stack the transmitted ray carries.
    struct Crossing;
    Crossing cross(std::uint32_t object, float object_ior) const;

  private:
    struct Medium {
        std::uint32_t object = 0;
        float ior = 1.0f;
    };

    int find(std::uint32_t object) const {
        for (int i = size_ - 1; i >= 0; --i)
            if (media_[i].object == object) return i;
        return -1;
    }
    void erase(int at) {
        for (int i = at; i + 1 < size_; ++i) media_[i] = media_[i + 1];
        --size_;
    }
    void push(std::uint32_t object, float ior) {
        if (size_ == kCapacity) erase(0);  // nested deeper than kCapacity: forget the outermost
        media_[size_++] = {object, ior};
    }

    std::array<Medium, kCapacity> media_{};
    int size_ = 0;
};

struct MediumStack::Crossing {
    float eta_from = 1.0f;
    float eta_to = 1.0f;
    MediumStack after;
};

inline MediumStack::Crossing MediumStack::cross(std::uint32_t object, float object_ior) const {
    Crossing c{ior(), 1.0f, *this};
    const int at = find(object);
    if (at < 0) {  // entering
        c.eta_to = object_ior;
        c.after.push(object, object_ior);
    } else if (at == size_ - 1) {  // leaving the innermost: into what contains it
        c.after.size_ = size_ - 1;
        c.eta_to = c.after.ior();
    } else {
        // Leaving an object that is not the innermost (overlapping glass): the ray stays
        // in the innermost medium, so it passes straight on.
        c.after.erase(at);
        c.eta_to = c.eta_from;
    }
    return c;
}

}  // namespace rt
