// The classes of light paths, in Heckbert's notation (L light, D diffuse or glossy, S specular,
// E eye), that a scene can produce and an integrator can account for. A scene's classes come from
// what it holds (integrators/scene_path_classes.h); each integrator declares those it covers
// (IntegratorInfo::covers), so `fluence info` can say which methods suit a scene and a render can
// warn which light its method will miss.
#pragma once

#include <string>

namespace fluence::integrators {

enum PathClass : unsigned {
    kEmitterSeen = 1u << 0,         // LE: lights and emissive surfaces seen directly
    kDirect = 1u << 1,              // LDE: direct lighting of diffuse and glossy surfaces, with shadows
    kSpecularSeen = 1u << 2,        // L(D)S+E: mirrors and glass seen from the eye, what they show lit directly
    kIndirect = 1u << 3,            // LD(D|S)*DE: interreflection between diffuse and glossy surfaces
    kCaustics = 1u << 4,            // LS+D...E: light through or off specular surfaces onto diffuse ones
    kDeltaLightCaustics = 1u << 5,  // caustics from point, spot and angle-0 distant lights (LS+D with a delta L)
    kVolumes = 1u << 6,             // scattering in participating media (V events)
    kSubsurface = 1u << 7,          // transport under surfaces (subsurface random walk or diffusion)
    kDeltaLights = 1u << 8,         // any light from delta lights, which only light sampling can reach
};

inline constexpr unsigned kPathClassCount = 9;
inline constexpr unsigned kAllPathClasses = (1u << kPathClassCount) - 1;

// "LE, LDE, ..." for the classes in `mask`, in the order above.
std::string describePathClasses(unsigned mask);

}  // namespace fluence::integrators
