// The UsdGeom surfaces the delegate tessellates itself -> render::MeshDesc, in world space: the
// implicit surfaces (Sphere, Cube, Cylinder, Cone, Capsule, Plane, Cylinder_1, Capsule_1) and
// NurbsPatch (evaluated by delegate/nurbs_patch.h; its attributes are tabled there).
//
// Each surface is centred at the prim's origin, as UsdGeom defines it; `axis` is the spine of the
// surfaces of revolution. Attributes read:
// | type     | attributes read (fallback)                                                          |
// |----------|--------------------------------------------------------------------------------------|
// | all      | primvars:displayColor (none; constant, optionally indexed — see below)               |
// | Sphere   | radius (1)                                                                            |
// | Cube     | size (2): the edge length                                                             |
// | Cylinder | radius (1), height (2), axis ("Z")                                                    |
// | Cone     | radius (1), height (2), axis ("Z"); base at -height/2, apex at +height/2 on the axis  |
// | Capsule  | radius (0.5), height (1): the cylinder part, hemispherical caps of `radius` added     |
// | Cylinder_1 | radiusTop (1), radiusBottom (1), height (2), axis ("Z"): a capped frustum         |
// | Capsule_1  | radiusTop (0.5), radiusBottom (0.5), height (1), axis ("Z"): spherical caps of     |
// |            | each radius joined by their tangent cone; radii differing by height or more fail  |
// | Plane    | width (2), length (2), axis ("Z"): a rectangle facing +axis, width along x (z for   |
// |          | axis X), length along y (z for axis Y); two triangles                               |
// A displayColor that is not constant warns and uses its first value (UsdGeom gives implicit
// surfaces no face or vertex order for uniform/vertex primvars to follow). A negative or
// non-finite size, radius, height, width or length, or an axis other than "X", "Y", "Z", raises
// SceneError naming the prim; a radius or size of 0 gives an empty mesh. Not read yet:
// orientation, doubleSided (every surface is two-sided), extent.
//
// Tessellation: a fixed resolution chosen so that the tessellated surface lies within
// kSilhouetteTolerance * radius of the analytic one everywhere (so no silhouette, from any view,
// is off by more than that). Vertices lie on the analytic surface; the error is the sag of each
// flat triangle between them:
//   - circles (Cylinder, Cone): N segments, the sag of a chord being r (1 - cos(pi / N)); the
//     smallest multiple of 4 with that <= tolerance is N = 72 (sag 0.095% of r);
//   - spheres (Sphere, Capsule caps): N segments of longitude and N/2 bands of latitude; the sag of
//     a band's planar quad is 1 - (distance of its plane from the centre), largest next to the
//     equator; the smallest multiple of 4 with every band within tolerance is N = 100 (sag 0.099%
//     of r), i.e. 9 800 triangles per sphere.
// Multiples of 4 keep the tessellation symmetric about the principal planes (vertices on the
// axes). Shading normals are smooth (the analytic normal at each vertex; a cone's apex gets one
// vertex per segment with the normal of that segment's middle) except on the Cube and on the flat
// caps of Cylinder and Cone, which are flat. Triangles wind counter-clockwise seen from outside;
// under a mirroring transform the winding is reversed so they still do.
#pragma once

#include <functional>
#include <string>

#include "core/matrix.h"
#include "delegate/prim_reader.h"
#include "render/scene_description.h"

namespace fluence::delegate {

// The largest distance between a tessellated implicit surface and the analytic one, relative to
// the radius.
inline constexpr double kSilhouetteTolerance = 1e-3;

// Segments around a circle (Cylinder, Cone) and around a sphere (Sphere, Capsule; a sphere has
// half as many bands of latitude), derived from kSilhouetteTolerance as described above.
int circleSegments();
int sphereSegments();

bool isImplicitType(const std::string& typeName);

// `convertColor` maps an authored colour (with the attribute's colorSpace, "" if none) into the
// rendering space; `warn` reports a problem that does not stop the render.
render::MeshDesc implicitMeshFromPrim(const PrimReader& prim, const Matrix4& toWorld,
                                      const std::function<RGB(const RGB&, const std::string&)>& convertColor,
                                      const std::function<void(const std::string&)>& warn);

}  // namespace fluence::delegate
