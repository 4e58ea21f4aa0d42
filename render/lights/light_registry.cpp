#include "render/lights/light_registry.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

#include "render/lights/cylinder_light.h"
#include "render/lights/disk_light.h"
#include "render/lights/distant_light.h"
#include "render/lights/dome_light.h"
#include "render/lights/line_light.h"
#include "render/lights/point_light.h"
#include "render/lights/rect_light.h"
#include "render/lights/sphere_light.h"

namespace fluence::render {

namespace {

struct LightKind {
    LightType type;
    std::unique_ptr<Light> (*make)(const LightDesc&);
    bool (*delta)(const LightDesc&);
};

template <class L>
std::unique_ptr<Light> make(const LightDesc& desc) {
    return std::make_unique<L>(desc);
}

bool never(const LightDesc&) { return false; }

// One row per LightType.
constexpr LightKind kLightKinds[] = {
    {LightType::Rect, make<RectLight>, never},
    {LightType::Disk, make<DiskLight>, never},
    {LightType::Sphere, [](const LightDesc& d) { return d.treatAsPoint ? make<PointLight>(d) : make<SphereLight>(d); },
     [](const LightDesc& d) { return d.treatAsPoint; }},
    {LightType::Cylinder,
     [](const LightDesc& d) { return d.treatAsLine ? make<LineLight>(d) : make<CylinderLight>(d); },
     [](const LightDesc& d) { return d.treatAsLine; }},
    {LightType::Distant, make<DistantLight>, [](const LightDesc& d) { return d.angleDegrees <= 0.0f; }},
    {LightType::Dome, make<DomeLight>, never},
};

const LightKind& kindOf(const LightDesc& desc) {
    const auto* kind = std::find_if(std::begin(kLightKinds), std::end(kLightKinds),
                                    [&](const LightKind& k) { return k.type == desc.type; });
    if (kind == std::end(kLightKinds))
        throw std::invalid_argument(desc.name + ": light type " + std::to_string(static_cast<int>(desc.type)) +
                                    " has no row in render/lights/light_registry.cpp");
    return *kind;
}

}  // namespace

std::unique_ptr<Light> makeLight(const LightDesc& desc) { return kindOf(desc).make(desc); }

bool isDeltaLight(const LightDesc& desc) { return kindOf(desc).delta(desc); }

}  // namespace fluence::render
