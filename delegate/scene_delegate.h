// The scene delegate: reads a USD stage into a render index and hands the render core its
// SceneDescription.
//
// This is the only place that knows USD schema names. Populating walks the stage's defined,
// active prims depth-first, skipping invisible subtrees and guide/proxy purposes, and inserts a
// render prim per Mesh or implicit surface, native instance, PointInstancer, shared prototype
// (delegate/instancing.h) and Volume (rprims), OpenVDBAsset (bprims), Camera and UsdLux light
// (sprims); syncing pulls each dirty prim's data through the adapter for its schema, creating a
// material sprim for every material a mesh binds and a texture bprim for every UsdUVTexture a
// material holds. Authored colours are converted into the rendering space through
// `convertColor`. Prim types it cannot render yet are skipped with one warning per type.
// A malformed prim is skipped with a warning naming it and the reason (render_index.h), or, with
// DelegateOptions::strict, raises SceneError naming the prim path, as other semantic errors do.
//
// Change tracking. Edits go through the delegate, which applies them to the stage and marks only
// the render prims they affect (render_index.h states the dirty-bit contract):
//   xformOp* / xformOpOrder on P      -> kDirtyTransform on every prim at or below P
//   points / topology / primvars of a mesh or implicit prim -> that rprim's data bits
//   any attribute of a light or camera -> that sprim
//   any attribute of an OpenVDBAsset or UsdUVTexture shader -> that bprim (volumes and
//                                        materials keep their data)
//   any attribute inside a Material    -> that material sprim (meshes keep their data)
//   material:binding*                  -> kDirtyMaterial on meshes at or below P
//   visibility / purpose / active, variant selections -> the subtree at P is removed and
//                                        populated again (new prims, all dirty), and every
//                                        prototype read from below P is dirtied
//   any attribute at or below a prototype's source prim -> that prototype (except the
//                                        transform of a native instance, which only moves it)
//   any attribute inside a native instance -> refused (SceneError): instance proxies are read-only
//   a new render time                  -> only prims whose transform or data is animated
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "delegate/dicing.h"
#include "delegate/material_adapter.h"
#include "delegate/prim_reader.h"
#include "delegate/render_index.h"
#include "delegate/render_settings_adapter.h"
#include "render/scene_description.h"
#include "scene/stage.h"

namespace fluence::texture {
class TextureSystem;
}

namespace fluence::delegate {

struct DelegateOptions {
    std::string cameraPath;    // "" = the render settings' camera, else the first Camera prim
    std::string settingsPath;  // "" = the stage's renderSettingsPrimPath
    // The image size: this when set (the command line), else the rendered product's, else the
    // render settings', else `defaultResolution`.
    std::optional<std::pair<int, int>> resolution;
    std::pair<int, int> defaultResolution{640, 480};
    DicingSettings dicing;            // how subdivision surfaces are tessellated for the camera
    double time = usd::kDefaultTime;  // the render time code; kDefaultTime: no frame (prim_reader.h)
    ColorConverter convertColor;      // authored colour + colour space -> rendering space
    Warn warn;                        // (prim path, message)
    // The purposes rendered (--purpose): these when set, else the render settings' includedPurposes.
    std::optional<std::vector<std::string>> purposes;
    // A missing OpenVDB file: a warning and the volume left out when true, else MissingAssetError.
    bool allowMissing = false;
    // A malformed prim (render_index.h): SceneError when true, else a warning and the prim skipped.
    bool strict = false;
    // A scene in which nothing emits gets the default lights (delegate/default_lights.h), with a
    // warning, unless this is false or the render settings' fluence:defaultLight is false.
    bool defaultLight = false;
    // Primvars (names without "primvars:") every mesh keeps for primvar RenderVars, whether or not
    // its material reads them (render::RenderScene::primvarAt).
    std::set<std::string> aovPrimvars;
    // Motion blur over the camera's shutter (delegate/motion_samples.h), unless this is false
    // (--no-motion-blur) or the render settings' disableMotionBlur is true.
    bool motionBlur = true;
    // Set: points and instances with velocities move from this frame to `time` at sync (a motion
    // step, delegate/motion_samples.h); kDefaultTime: they are read as authored.
    double velocityFrame = usd::kDefaultTime;
    // Where a displacement texture is read when meshes are diced (delegate/displacement.h); null:
    // a textured displacement takes its texture's fallback.
    std::shared_ptr<texture::TextureSystem> textures;
};

class SceneDelegate {
public:
    // Populates the render index from the whole stage (every prim dirty; call sync()).
    SceneDelegate(usd::Stage& stage, DelegateOptions options);

    // Syncs every dirty render prim; returns how many were synced.
    std::size_t sync();
    // The render core's input, from the synced index: world-space meshes, materials, lights and
    // the chosen camera. Throws SceneError when the camera cannot be chosen.
    render::SceneDescription sceneDescription() const;
    const std::string& cameraPath() const { return cameraPath_; }
    const std::optional<RenderSettingsDesc>& renderSettings() const { return renderSettings_; }
    // The image size and framing the render uses (see DelegateOptions::resolution).
    std::pair<int, int> resolution() const;
    render::ImageFraming framing() const;
    const RenderIndex& renderIndex() const { return index_; }
    // Every malformed prim the last populate and sync left out or read a value of as not authored
    // (none under DelegateOptions::strict, which raises SceneError instead), in path order.
    std::vector<MalformedPrim> malformedPrims() const;

    // Edits (see the table above). Each returns after marking; call sync() to pull the changes.
    void setTime(double time);
    // Moves the index to the motion step at `time` of the frame at `velocityFrame` (motion_samples.h):
    // what setTime marks, and the point-based prims that move by velocities, are synced again at
    // `time`, with no warning given (the frame gave them) and the render settings kept. Call sync().
    void setMotionStep(double time, double velocityFrame);
    void setAttribute(const std::string& primPath, const std::string& name, const usd::Value& value);
    void setVariantSelection(const std::string& primPath, const std::string& variantSet, const std::string& selection);

private:
    void populate(const std::string& root);
    // Marks what a change of time changes: failed prims (all), animated transforms and data, and,
    // with `byVelocities`, the prims that move by velocities (motion_samples.h).
    void markTimeDependent(bool byVelocities);
    void repopulate(const std::string& primPath);
    // Creates, re-sources or removes prototypes so that every instance's prototype exists.
    void reconcilePrototypes();
    // Dirties the prototypes an edit of `attribute` on `primPath` changes ("" = a structural
    // edit); returns whether any was.
    bool markPrototypesReading(const std::string& primPath, const std::string& attribute = "");
    void chooseCamera();
    // The description with subdivision surfaces diced for `camera` by `dicing`, every rate scaled
    // by `scale`; counts the triangles they took.
    render::SceneDescription describe(const render::Camera& camera, const DicingSettings& dicing, float scale,
                                      std::size_t& subdivisionTriangles) const;
    // The render core's description of a Volume: its material's parameters and its grids (nullopt,
    // with a warning, when it has no density field). Raises MissingAssetError when a grid file is
    // missing (with DelegateOptions::allowMissing: a warning, and nullopt).
    std::optional<render::VolumeDesc> volumeDesc(const VolumeRprim& volume) const;
    SyncContext context() const {
        return {stage_,    options_.time,   options_.convertColor, options_.warn,
                purposes_, options_.strict, options_.velocityFrame};
    }

    usd::Stage& stage_;
    DelegateOptions options_;
    RenderIndex index_;
    std::map<std::string, std::string> prototypes_;  // prototype key -> prototype render prim path
    int nextPrototype_ = 1;
    std::optional<RenderSettingsDesc> renderSettings_;
    IncludedPurposes purposes_;
    std::string cameraPath_;
    std::map<std::string, std::string> walkMalformed_;  // prim path -> why populate ignored a value of it
};

struct DelegateResult {
    render::SceneDescription scene;
    std::string cameraPath;
    std::optional<RenderSettingsDesc> renderSettings;
    std::pair<int, int> resolution;
    render::ImageFraming framing;
};

// Populates, syncs and describes a stage in one call (what a single-frame render needs).
DelegateResult populateScene(usd::Stage& stage, const DelegateOptions& options);

}  // namespace fluence::delegate
