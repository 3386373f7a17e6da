#include "core/gltf_material.h"

#include <algorithm>

#include <glm/common.hpp>

namespace rt {

Material phong_of(const tinygltf::Material& g) {
    const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
    vec3 base(1.0f);
    if (pbr.baseColorFactor.size() >= 3)
        base = vec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]);
    const float metallic = std::clamp(static_cast<float>(pbr.metallicFactor), 0.0f, 1.0f);
    const float roughness = std::clamp(static_cast<float>(pbr.roughnessFactor), 0.0f, 1.0f);
    Material m;
    m.name = g.name;
    // A smooth metal is a mirror of its colour; what a surface does not mirror it
    // scatters: a rough metal looks like a coloured matte one, a dielectric is its base
    // colour with a 4 % highlight. The highlight narrows as the roughness falls.
    m.reflectivity = metallic * (1.0f - roughness);
    m.kd = base * (1.0f - m.reflectivity);
    m.ka = m.kd;
    m.ks = glm::mix(vec3(0.04f), base, metallic);
    const float alpha = std::max(roughness * roughness, 0.03f);  // GGX's alpha
    m.shininess = std::clamp(2.0f / (alpha * alpha) - 2.0f, 1.0f, 2000.0f);
    if (g.emissiveFactor.size() == 3)
        m.emission = vec3(g.emissiveFactor[0], g.emissiveFactor[1], g.emissiveFactor[2]);
    if (const auto t = g.extensions.find("KHR_materials_transmission"); t != g.extensions.end())
        if (t->second.Has("transmissionFactor"))
            m.transparency = std::clamp(
                static_cast<float>(t->second.Get("transmissionFactor").GetNumberAsDouble()), 0.0f,
                1.0f);
    if (const auto i = g.extensions.find("KHR_materials_ior"); i != g.extensions.end())
        if (i->second.Has("ior")) {
            const double ior = i->second.Get("ior").GetNumberAsDouble();
            if (ior > 0.0) m.ior = static_cast<float>(ior);
        }
    return m;
}

}  // namespace rt
