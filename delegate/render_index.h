// The render index: the delegate's render prims, each synced from the stage when dirty.
//
// As in Hydra, prims come in kinds: rprims (geometry: meshes and tessellated implicit surfaces;
// prototypes, native instances and point instancers (delegate/instancing.h); UsdVol volumes;
// BasisCurves and NurbsCurves, delegate/curves_rprim.h),
// sprims (state: cameras, lights, materials) and bprims (buffers: the OpenVDB field assets
// volumes name, and the UsdUVTexture images materials use; the render core loads the files).
//
// The dirty-bit contract (see also scene_delegate.h, which maps stage edits to bits):
//   - A prim is inserted with every bit dirty and synced once before the first render.
//   - sync() pulls from the stage only what its dirty bits name, then clears them and counts the
//     sync (tests assert these counts: a clean prim is never asked for data).
//   - Mesh rprims keep their geometry in object space: kDirtyTransform alone re-transforms it
//     without re-reading or re-triangulating anything. Topology, points, primvars and material
//     binding re-read the mesh (the GeomSubset split depends on bindings), except that new points
//     alone on a subdivision surface keep its OpenSubdiv topology.
//   - Prototypes live at synthetic paths (/__Prototype_N) and read the subtree at their source
//     prim; any dirty bit re-reads it. Instances and point instancers hold transforms only:
//     moving one never re-reads a prototype.
//   - Sprims are small: any dirty bit re-reads the prim.
//   - Each prim records whether what it read is animated (time samples), so that a change of
//     render time dirties only animated prims.
//   - One bad prim never sinks a render (Hydra's behaviour): a sync that raises SceneError (a
//     malformed prim: face counts that do not match the indices, a GeomSubset index out of
//     range, a loop-scheme mesh with quads, a primvar of the wrong size, a bad xformOp) leaves
//     the prim failed(), with one warning naming it and the reason, and the scene is described
//     without it; the next sync (an edit, a new render time) tries it again. In a prototype, only
//     the malformed prim (and what lies below it) is left out: the prototype keeps the rest. With
//     SyncContext::strict the SceneError is raised instead. A MissingAssetError is always raised.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "delegate/instancing.h"
#include "delegate/material_adapter.h"
#include "delegate/mesh_light.h"
#include "delegate/volume_adapter.h"
#include "delegate/prim_reader.h"
#include "delegate/subdivision_mesh.h"
#include "delegate/sync_context.h"
#include "render/scene_description.h"
#include "scene/stage.h"

namespace fluence::delegate {

enum DirtyBits : std::uint32_t {
    kClean = 0,
    kDirtyTransform = 1u << 0,  // the prim's or an ancestor's xformOps
    kDirtyTopology = 1u << 1,   // faces, holes, subsets, implicit shape parameters
    kDirtyPoints = 1u << 2,
    kDirtyPrimvars = 1u << 3,  // normals, displayColor
    kDirtyMaterial = 1u << 4,  // material binding
    kDirtyParams = 1u << 5,    // a sprim's own attributes
    kAllDirty = ~0u,
};

class RenderPrim {
public:
    enum class Kind {
        Mesh,
        Prototype,
        Instance,
        PointInstancer,
        Volume,
        Camera,
        Light,
        Material,
        Field,
        Texture,
        Curves,
        Points
    };

    RenderPrim(Kind kind, std::string path) : kind_(kind), path_(std::move(path)) {}
    virtual ~RenderPrim() = default;

    Kind kind() const { return kind_; }
    const std::string& path() const { return path_; }
    std::uint32_t dirtyBits() const { return dirty_; }
    void markDirty(std::uint32_t bits) { dirty_ |= bits; }
    int syncCount() const { return syncCount_; }
    bool transformAnimated() const { return transformAnimated_; }
    bool dataAnimated() const { return dataAnimated_; }
    // Whether the last sync failed (the prim is left out of the scene), and why: the SceneError's
    // message, naming the prim (or the ancestor, material or subset) at fault.
    bool failed() const { return !failure_.empty(); }
    const std::string& failure() const { return failure_; }

    // Pulls what the dirty bits name from the stage and clears them (no-op when clean).
    void sync(const SyncContext& context);

    // Local-to-world transform of the prim at path() (identity for synthetic paths).
    const Matrix4& world() const { return world_; }

protected:
    virtual void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) = 0;
    // The stage prim the data is read from (path() unless the render prim is synthetic).
    virtual const std::string& sourcePath() const { return path_; }
    // Whether what syncData read from `source` is animated (default: a non-transform attribute
    // of the prim itself has time samples).
    virtual bool readsAnimatedData(const usd::PrimSpec& source) const;

private:
    Kind kind_;
    std::string path_;
    std::uint32_t dirty_ = kAllDirty;
    int syncCount_ = 0;
    Matrix4 world_ = Matrix4::identity();
    bool transformAnimated_ = false, dataAnimated_ = false;
    std::string failure_;
};

// Geometry split into one part per bound material: a mesh's or a prototype's (a prototype's
// curves and point sets too). Polygon meshes
// and implicit surfaces are triangulated at sync; subdivision surfaces are read at sync and
// diced for the camera when the scene is described (delegate/subdivision_mesh.h).
class SurfaceRprim : public RenderPrim {
public:
    struct Part {
        render::MeshDesc objectSpace;  // object space (a prototype's own space for a prototype)
        std::string materialPath;
    };
    struct Subdivided {
        std::shared_ptr<const SubdivisionMesh> mesh;
        Matrix4 placement;  // the subdivision mesh's object space -> this prim's object space
    };
    const std::vector<Part>& parts() const { return parts_; }
    const std::vector<Subdivided>& subdivided() const { return subdivided_; }
    const std::vector<PrototypeCurves>& curves() const { return curves_; }  // a prototype's; in its space
    const std::vector<PrototypePoints>& points() const { return points_; }  // a prototype's; in its space
    // The materials the geometry binds (parts', subdivision meshes', curves' and points').
    std::vector<std::string> materialPaths() const;
    // How many syncs read (and triangulated or tessellated) the geometry; transform-only syncs
    // do not.
    int dataReads() const { return dataReads_; }

protected:
    using RenderPrim::RenderPrim;
    std::vector<Part> parts_;
    std::vector<Subdivided> subdivided_;
    std::vector<PrototypeCurves> curves_;
    std::vector<PrototypePoints> points_;
    int dataReads_ = 0;
};

// A Mesh (polygons or a subdivision surface), or an implicit surface tessellated into one.
class MeshRprim final : public SurfaceRprim {
public:
    explicit MeshRprim(std::string path) : SurfaceRprim(Kind::Mesh, std::move(path)) {}
    // The parts in world space (a subdivision surface diced for the camera).
    std::vector<Part> worldParts(const DicingContext& dicing) const;
    // Its UsdLux MeshLightAPI (delegate/mesh_light.h), when it applies it.
    const std::optional<MeshLight>& meshLight() const { return meshLight_; }

private:
    void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) override;
    bool readsAnimatedData(const usd::PrimSpec& source) const override;
    std::optional<MeshLight> meshLight_;
    bool skinned_ = false, skinAnimated_ = false;  // posed by UsdSkel (delegate/skel_binding.h); the pose is animated
};

// Geometry shared by instances: every surface below `source`, in the source's space (with the
// source's own transform for a point-instancer prototype).
class PrototypeRprim final : public SurfaceRprim {
public:
    PrototypeRprim(std::string path, std::string source, bool includeSourceTransform)
        : SurfaceRprim(Kind::Prototype, std::move(path)),
          source_(std::move(source)),
          includeSourceTransform_(includeSourceTransform) {}
    const std::string& source() const { return source_; }
    bool includesSourceTransform() const { return includeSourceTransform_; }
    // The lights below the source, in the source's space: each instance places a copy.
    const std::vector<render::LightDesc>& lights() const { return lights_; }
    // The mesh lights among its parts (PrototypeContents::meshLights), by prim path.
    const std::map<std::string, MeshLight>& meshLights() const { return meshLights_; }
    // The malformed prims below the source the last sync left out.
    const std::vector<MalformedPrim>& malformed() const { return malformed_; }
    // Reads from another source prim from the next sync on.
    void setSource(std::string source) {
        source_ = std::move(source);
        markDirty(kAllDirty);
    }

private:
    void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) override;
    const std::string& sourcePath() const override { return source_; }
    bool readsAnimatedData(const usd::PrimSpec& source) const override;
    std::string source_;
    bool includeSourceTransform_;
    std::vector<render::LightDesc> lights_;
    std::map<std::string, MeshLight> meshLights_;
    std::vector<MalformedPrim> malformed_;
    bool posedByAnimation_ = false;  // PrototypeContents::posedByAnimation
};

// A native instance: an instanceable prim placing the prototype its key names at world().
class InstanceRprim final : public RenderPrim {
public:
    explicit InstanceRprim(std::string path) : RenderPrim(Kind::Instance, std::move(path)) {}
    const std::string& prototypeKey() const { return prototypeKey_; }

private:
    void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) override;
    std::string prototypeKey_;
};

// A UsdGeomPointInstancer: instance transforms relative to world().
class PointInstancerRprim final : public RenderPrim {
public:
    explicit PointInstancerRprim(std::string path) : RenderPrim(Kind::PointInstancer, std::move(path)) {}
    const PointInstances& instances() const { return instances_; }

private:
    void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) override;
    PointInstances instances_;
};

// A UsdVol Volume: its `field:NAME` relationships to field asset prims (FieldBprims).
class VolumeRprim final : public RenderPrim {
public:
    struct Field {
        std::string name;       // the relationship's NAME: density, temperature, ...
        std::string assetPrim;  // the OpenVDBAsset prim: a FieldBprim in the index
    };
    explicit VolumeRprim(std::string path) : RenderPrim(Kind::Volume, std::move(path)) {}
    const std::vector<Field>& fields() const { return fields_; }
    // Its volume material, read when the volume syncs (delegate/volume_adapter.h).
    const VolumeMaterial& material() const { return material_; }

private:
    void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) override;
    std::vector<Field> fields_;
    VolumeMaterial material_;
};

// A UsdVol OpenVDBAsset (or Field3DAsset): one grid of one file. Editing it re-syncs only this
// bprim; the volumes naming it keep their data.
class FieldBprim final : public RenderPrim {
public:
    explicit FieldBprim(std::string path) : RenderPrim(Kind::Field, std::move(path)) {}
    const std::string& filePath() const { return filePath_; }  // resolved; "" when not authored
    const std::string& gridName() const { return gridName_; }  // fieldName: the grid in the file
    int fieldIndex() const { return fieldIndex_; }             // -1 when not authored
    bool fileFound() const { return fileFound_; }

private:
    void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) override;
    std::string filePath_, gridName_;
    int fieldIndex_ = -1;
    bool fileFound_ = false;
};

// A UsdUVTexture shader of a material's network: its image file and how to read it.
class TextureBprim final : public RenderPrim {
public:
    explicit TextureBprim(std::string path) : RenderPrim(Kind::Texture, std::move(path)) {}
    const std::string& filePath() const { return filePath_; }  // resolved; "" when not authored
    // inputs:sourceColorSpace: "auto", "raw" or "sRGB".
    const std::string& sourceColorSpace() const { return sourceColorSpace_; }
    // inputs:wrapS / inputs:wrapT: "useMetadata", "black", "clamp", "repeat" or "mirror".
    const std::string& wrapS() const { return wrapS_; }
    const std::string& wrapT() const { return wrapT_; }
    // Whether the file exists; UDIM paths (<UDIM>) count as found when any tile does.
    bool fileFound() const { return fileFound_; }

private:
    void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) override;
    std::string filePath_, sourceColorSpace_, wrapS_, wrapT_;
    bool fileFound_ = false;
};

class CameraSprim final : public RenderPrim {
public:
    explicit CameraSprim(std::string path) : RenderPrim(Kind::Camera, std::move(path)) {}
    const render::CameraDesc& camera() const { return camera_; }

private:
    void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) override;
    render::CameraDesc camera_;
};

class LightSprim final : public RenderPrim {
public:
    explicit LightSprim(std::string path) : RenderPrim(Kind::Light, std::move(path)) {}
    const std::optional<render::LightDesc>& light() const { return light_; }  // nullopt: not renderable

private:
    void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) override;
    std::optional<render::LightDesc> light_;
};

class MaterialSprim final : public RenderPrim {
public:
    explicit MaterialSprim(std::string path) : RenderPrim(Kind::Material, std::move(path)) {}
    const render::MaterialDesc& material() const { return material_; }
    // The UsdUVTexture shaders inside the material (TextureBprims), in namespace order.
    const std::vector<std::string>& textures() const { return textures_; }

private:
    void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) override;
    bool readsAnimatedData(const usd::PrimSpec& source) const override;
    render::MaterialDesc material_;
    std::vector<std::string> textures_;
};

class RenderIndex {
public:
    void insert(std::unique_ptr<RenderPrim> prim);
    // Removes the prim at `path` and every prim below it.
    void removeSubtree(const std::string& path);
    RenderPrim* find(const std::string& path) const;
    // Marks the prim at `path` and every prim below it.
    void markSubtreeDirty(const std::string& path, std::uint32_t bits, std::optional<RenderPrim::Kind> kind = {});
    // Syncs every dirty prim: materials after geometry (meshes and prototypes name the materials
    // they need, and a material sprim is created for each), textures last (materials name them).
    // Returns how many prims were synced.
    std::size_t sync(const SyncContext& context);

    // Prims in path order.
    const std::map<std::string, std::unique_ptr<RenderPrim>>& prims() const { return prims_; }

private:
    std::map<std::string, std::unique_ptr<RenderPrim>> prims_;
};

// A prim's local-to-world transform at `time`, composed from the root down (honouring
// !resetXformStack!), and whether an xformOp on the way is time-sampled.
struct WorldTransform {
    Matrix4 matrix = Matrix4::identity();
    bool animated = false;
};
WorldTransform worldTransformOf(const usd::Stage& stage, const std::string& path, double time, const Warn& warn);

// True when `path` is `root` or lies below it.
bool isAtOrBelow(const std::string& path, const std::string& root);

// OpenVDBAsset or Field3DAsset: the field prims FieldBprims read.
bool isFieldAssetType(const std::string& typeName);

// Whether a resolved asset path names an existing file; a UDIM path (with <UDIM>) when any of
// its tiles 1001-1100 exists.
bool assetFileExists(const std::string& path);

}  // namespace fluence::delegate
