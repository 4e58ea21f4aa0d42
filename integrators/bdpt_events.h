// The light path expression events of bidirectional path tracing (integrators/bdpt.h): each
// strategy (s, t) joins a camera subpath z_1 ... z_{t-1} to a light subpath y_{s-1} ... y_1 and
// its light, so its path reads, from the camera, C, the camera vertices' events, the light
// vertices' events in reverse order of their drawing, and the light's event. Every vertex is
// labelled as `path` labels it (integrators/path_events.h), in the radiance view whichever
// subpath drew it: from the direction towards the camera to the direction towards the light, so
// that a light vertex's share of each lobe kind is that of the adjoint BSDF its subpath was
// weighted by (render/bsdf.h, TRANSPORT MODE: f*(wo, wi) = f(wi, wo)).
#pragma once

#include <span>
#include <vector>

#include "integrators/bdpt_vertex.h"
#include "integrators/light_path_tracker.h"

namespace fluence::integrators::bdpt {

// The events of vertex v, whose BSDF (or phase function) `sh` is, on a path that goes on from it
// towards the camera along `toCamera` and towards the light along `toLight` (unit, world space);
// `delta`: it was left by a delta lobe (then one singular event, R or T by the sides).
VertexEvents scatteringEvents(const Shading& sh, const Vertex& v, const Vec3f& toCamera, const Vec3f& toLight,
                              bool delta);

// The events from a join towards the light: `joined` (the events at the join, camera side first),
// then `drawn` (the light subpath's vertices y_1 ... y_n as drawn, each as scatteringEvents gave
// it) from y_n back to y_1. `path` is cleared and refilled (its capacity reused).
void towardsLight(std::span<const VertexEvents> joined, std::span<const VertexEvents> drawn,
                  std::vector<VertexEvents>& path);

}  // namespace fluence::integrators::bdpt
