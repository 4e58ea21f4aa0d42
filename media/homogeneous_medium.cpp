#include "media/homogeneous_medium.h"

namespace fluence::media {

HomogeneousMedium::HomogeneousMedium(const MediumProperties& properties) : properties_(properties) {}

void HomogeneousMedium::majorants(const Vec3f&, const Vec3f&, float tMin, float tMax,
                                  FunctionRef<bool(const MajorantSegment&)> visit) const {
    const RGB sigmaT = properties_.sigmaA + properties_.sigmaS;
    if (tMin < tMax) visit(MajorantSegment{tMin, tMax, sigmaT, sigmaT});
}

void HomogeneousMedium::extinctionPieces(const Vec3f&, const Vec3f&, float tMin, float tMax,
                                         FunctionRef<bool(const ExtinctionPiece&)> visit) const {
    const RGB sigmaT = properties_.sigmaA + properties_.sigmaS;
    if (tMin < tMax) visit(ExtinctionPiece{tMin, tMax, {1.0, 0.0, 0.0, 0.0}, Vec3d(sigmaT.x, sigmaT.y, sigmaT.z)});
}

}  // namespace fluence::media
