#include "delegate/mesh_source.h"

#include "delegate/tet_mesh.h"

namespace fluence::delegate {

MeshSource meshSource(const usd::Stage& stage, const usd::PrimSpec& prim, double time, const Warn& warn) {
    MeshSource source;
    if (prim.typeName == "TetMesh") source.copy = tetMeshSurface(PrimReader(prim, time));
    const usd::PrimSpec& mesh = source.prim(prim);
    if (mesh.typeName != "Mesh") return source;
    source.pose = skinnedPose(stage, mesh, time, warn);
    if (source.pose) source.copy = posedMeshSpec(mesh, *source.pose);
    return source;
}

}  // namespace fluence::delegate
