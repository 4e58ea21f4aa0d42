#include "integrators/bdpt_events.h"

#include "integrators/path_events.h"

namespace fluence::integrators::bdpt {

VertexEvents scatteringEvents(const Shading& sh, const Vertex& v, const Vec3f& toCamera, const Vec3f& toLight,
                              bool delta) {
    if (!sh.bsdf()) return VertexEvents(volumeEvent(v.media.inSubsurface()));
    const Frame& frame = sh.surface().frame;
    return surfaceEvents(*sh.bsdf(), frame.toLocal(toCamera), frame.toLocal(toLight), delta);
}

void towardsLight(std::span<const VertexEvents> joined, std::span<const VertexEvents> drawn,
                  std::vector<VertexEvents>& path) {
    path.assign(joined.begin(), joined.end());
    path.insert(path.end(), drawn.rbegin(), drawn.rend());
}

}  // namespace fluence::integrators::bdpt
