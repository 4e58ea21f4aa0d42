#include "delegate/implicit_geometry.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "delegate/nurbs_patch.h"

namespace fluence::delegate {

namespace {

constexpr double kPi = std::numbers::pi;

// The sag of the flattest-fitting tessellation of a unit sphere with `segments` of longitude and
// segments/2 bands of latitude: the largest 1 - (distance from the centre to a band's plane).
// Each band's quads are planar (two parallel chords), so one plane per band covers both of its
// triangles; bands next to the equator are the largest.
double sphereSag(int segments) {
    const int bands = segments / 2;
    const double dphi = 2.0 * kPi / segments;
    auto point = [](double theta, double phi) {
        return Vec3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    };
    double worst = 0.0;
    for (int k = 0; k < bands / 2; ++k) {  // the northern half; the southern mirrors it
        double theta1 = kPi * k / bands, theta2 = kPi * (k + 1) / bands;
        Vec3d a = point(theta1, 0.0), b = point(theta2, 0.0), c = point(theta2, dphi);
        Vec3d n = cross(b - a, c - a);
        worst = std::max(worst, 1.0 - std::abs(dot(n, a)) / length(n));
    }
    return worst;
}

int smallestMultipleOf4(double (*sag)(int)) {
    int n = 4;
    while (sag(n) > kSilhouetteTolerance) n += 4;
    return n;
}

double circleSag(int segments) { return 1.0 - std::cos(kPi / segments); }

// Triangles in object space, before the world transform.
struct Builder {
    std::vector<Vec3d> points, normals;  // one normal per vertex
    std::vector<std::uint32_t> indices;  // 3 per triangle, counter-clockwise seen from outside

    std::uint32_t vertex(const Vec3d& p, const Vec3d& n) {
        points.push_back(p);
        normals.push_back(n);
        return static_cast<std::uint32_t>(points.size() - 1);
    }
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) { indices.insert(indices.end(), {a, b, c}); }
};

// A surface of revolution's profile: distance from the axis, position along it, and the outward
// normal in that (radial, axial) plane.
struct ProfilePoint {
    double radius, along;
    double normalRadial, normalAlong;
    bool operator==(const ProfilePoint&) const = default;
};

// Maps (u, v, w), w along the spine, to object space for `axis`: a rotation (cyclic permutation
// of the coordinates), so windings are kept.
Vec3d onAxis(char axis, const Vec3d& uvw) {
    if (axis == 'X') return {uvw.z, uvw.x, uvw.y};
    if (axis == 'Y') return {uvw.y, uvw.z, uvw.x};
    return uvw;
}

// Sweeps `profile` around the axis in `segments` steps. Consecutive profile points are joined by
// a band of quads (a fan of triangles where one end is on the axis), wound so that a step
// (d radius, d along) faces (-d along, d radius) in the (radial, axial) plane: profiles run from
// +w to -w down the outside, from the axis outwards on a cap facing +w and inwards on one facing
// -w. A point on the axis gets one vertex per segment, its normal taken at the segment's middle.
void lathe(Builder& out, const std::vector<ProfilePoint>& profile, int segments, char axis) {
    const double dphi = 2.0 * kPi / segments;
    auto ring = [&](const ProfilePoint& p) {
        std::vector<std::uint32_t> row(static_cast<std::size_t>(segments));
        bool pole = p.radius == 0.0;
        for (int j = 0; j < segments; ++j) {
            double phi = dphi * (j + (pole ? 0.5 : 0.0));
            double c = std::cos(phi), s = std::sin(phi);
            row[static_cast<std::size_t>(j)] =
                out.vertex(onAxis(axis, {p.radius * c, p.radius * s, p.along}),
                           onAxis(axis, {p.normalRadial * c, p.normalRadial * s, p.normalAlong}));
        }
        return row;
    };
    std::vector<std::uint32_t> upper = ring(profile.front());
    for (std::size_t i = 1; i < profile.size(); ++i) {
        const ProfilePoint& a = profile[i - 1];
        const ProfilePoint& b = profile[i];
        if (a == b) continue;  // a zero-length step (a capsule of height 0) adds nothing
        std::vector<std::uint32_t> lower = ring(b);
        if (a.radius != b.radius || a.along != b.along) {
            for (std::size_t j = 0; j < upper.size(); ++j) {
                std::size_t k = (j + 1) % upper.size();
                if (b.radius != 0.0) out.triangle(upper[j], lower[j], lower[k]);
                if (a.radius != 0.0) out.triangle(upper[j], lower[k], upper[k]);
            }
        }
        upper = std::move(lower);
    }
}

// A sphere of `radius` cut at the equator, the halves `height` apart along the axis (a Sphere
// when height is 0), with `segments` of longitude and segments/2 bands of latitude.
std::vector<ProfilePoint> capsuleProfile(double radius, double height, int segments) {
    const int bands = segments / 2;  // even: the equator is a ring of vertices
    std::vector<ProfilePoint> profile;
    for (int k = 0; k <= bands; ++k) {
        if (2 * k == bands) {  // the equators of both halves (the same ring when height is 0)
            profile.push_back({radius, 0.5 * height, 1.0, 0.0});
            profile.push_back({radius, -0.5 * height, 1.0, 0.0});
            continue;
        }
        double theta = kPi * k / bands;
        double s = k == 0 || k == bands ? 0.0 : std::sin(theta), c = std::cos(theta);
        double centre = 2 * k < bands ? 0.5 * height : -0.5 * height;
        profile.push_back({radius * s, centre + radius * c, s, c});
    }
    return profile;
}

// Capsule_1 with different radii: spheres of radius `top` at +height/2 and `bottom` at -height/2
// joined by the cone tangent to both (C1, as UsdGeomCapsule_1 defines it), whose outward normal
// makes the polar angle acos((top - bottom) / height) with the axis. Each cap keeps the sphere's
// steps of latitude (pi / (segments/2)) and ends at the tangent circle.
std::vector<ProfilePoint> taperedCapsuleProfile(double top, double bottom, double height, int segments) {
    const int bands = segments / 2;
    const double tangent = std::acos((top - bottom) / height);
    std::vector<ProfilePoint> profile;
    auto onSphere = [&](double radius, double centre, double theta) {
        const double s = theta == 0.0 || theta == kPi ? 0.0 : std::sin(theta), c = std::cos(theta);
        profile.push_back({radius * s, centre + radius * c, s, c});
    };
    for (int k = 0; kPi * k / bands < tangent; ++k) onSphere(top, 0.5 * height, kPi * k / bands);
    onSphere(top, 0.5 * height, tangent);
    onSphere(bottom, -0.5 * height, tangent);
    for (int k = 0; k <= bands; ++k)
        if (kPi * k / bands > tangent) onSphere(bottom, -0.5 * height, kPi * k / bands);
    return profile;
}

// A cylinder whose ends have radii `top` (at +height/2) and `bottom`, with a flat cap on each end
// of non-zero radius: Cylinder, Cylinder_1 and (top 0) Cone.
void frustum(Builder& out, double top, double bottom, double height, char axis) {
    const double up = 0.5 * height, down = -0.5 * height;
    const int n = circleSegments();
    if (top > 0.0) lathe(out, {{0.0, up, 0.0, 1.0}, {top, up, 0.0, 1.0}}, n, axis);
    const double slant = std::hypot(height, bottom - top);
    if (slant > 0.0)
        lathe(
            out,
            {{top, up, height / slant, (bottom - top) / slant}, {bottom, down, height / slant, (bottom - top) / slant}},
            n, axis);
    if (bottom > 0.0) lathe(out, {{bottom, down, 0.0, -1.0}, {0.0, down, 0.0, -1.0}}, n, axis);
}

// UsdGeomPlane: a width x length rectangle through the origin facing +axis; width along x (along z
// when the axis is X), length along y (along z when the axis is Y).
void plane(Builder& out, double width, double length, char axis) {
    Vec3d n(0.0), u(0.0), v(0.0);
    const int a = axis - 'X';
    n[a] = 1.0;
    u[axis == 'X' ? 2 : 0] = 0.5 * width;
    v[axis == 'Y' ? 2 : 1] = 0.5 * length;
    if (dot(cross(u, v), n) < 0.0) std::swap(u, v);  // counter-clockwise seen from +axis
    std::uint32_t p0 = out.vertex(-u - v, n), p1 = out.vertex(u - v, n), p2 = out.vertex(u + v, n),
                  p3 = out.vertex(v - u, n);
    out.triangle(p0, p1, p2);
    out.triangle(p0, p2, p3);
}

void cube(Builder& out, double size) {
    const double h = 0.5 * size;
    for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {1.0, -1.0}) {
            Vec3d n(0.0), u(0.0), v(0.0);
            n[axis] = sign;
            u[(axis + 1) % 3] = h;
            v[(axis + 2) % 3] = sign * h;  // (u, v, n) right-handed, so (+u+v, -u+v, ...) winds outwards
            Vec3d centre = n * h;
            std::uint32_t a = out.vertex(centre - u - v, n), b = out.vertex(centre + u - v, n);
            std::uint32_t c = out.vertex(centre + u + v, n), d = out.vertex(centre - u + v, n);
            out.triangle(a, b, c);
            out.triangle(a, c, d);
        }
    }
}

double nonNegative(const PrimReader& prim, const char* name, double fallback) {
    double value = prim.number({name}, fallback);
    if (!std::isfinite(value) || value < 0.0)
        prim.fail("'" + std::string(name) + "' must be a finite, non-negative number, got " + std::to_string(value));
    return value;
}

char axisOf(const PrimReader& prim) {
    std::string axis = prim.token({"axis"}, "Z");
    if (axis != "X" && axis != "Y" && axis != "Z")
        prim.fail("axis must be \"X\", \"Y\" or \"Z\", got \"" + axis + "\"");
    return axis[0];
}

std::optional<RGB> displayColor(const PrimReader& prim,
                                const std::function<RGB(const RGB&, const std::string&)>& convertColor,
                                const std::function<void(const std::string&)>& warn) {
    const std::string name = "primvars:displayColor";
    std::optional<std::vector<double>> values = prim.numbers(name, 3);
    if (!values || values->empty()) return std::nullopt;
    std::size_t element = 0;
    std::size_t count = values->size() / 3;
    if (auto indices = prim.numbers(name + ":indices", 1); indices && !indices->empty()) {
        double i = indices->front();
        if (i < 0 || i >= static_cast<double>(values->size() / 3))
            prim.fail("'" + name + ":indices' holds " + std::to_string(static_cast<long long>(i)) + ", outside the " +
                      std::to_string(values->size() / 3) + " values of '" + name + "'");
        element = static_cast<std::size_t>(i);
        count = indices->size();
    }
    std::string interpolation = prim.attributeMetadata(name, "interpolation").value_or("constant");
    if (interpolation != "constant" && count > 1)
        warn("'" + name + "' with " + interpolation +
             " interpolation is not supported on implicit surfaces (only constant); using its first value");
    RGB color(Vec3d((*values)[3 * element], (*values)[3 * element + 1], (*values)[3 * element + 2]));
    return convertColor(color, prim.attributeMetadata(name, "colorSpace").value_or(""));
}

}  // namespace

int circleSegments() {
    static const int n = smallestMultipleOf4(circleSag);
    return n;
}

int sphereSegments() {
    static const int n = smallestMultipleOf4(sphereSag);
    return n;
}

bool isImplicitType(const std::string& t) {
    return t == "Sphere" || t == "Cube" || t == "Cylinder" || t == "Cone" || t == "Capsule" || t == "Plane" ||
           t == "Cylinder_1" || t == "Capsule_1" || t == "NurbsPatch";
}

render::MeshDesc implicitMeshFromPrim(const PrimReader& prim, const Matrix4& toWorld,
                                      const std::function<RGB(const RGB&, const std::string&)>& convertColor,
                                      const std::function<void(const std::string&)>& warn) {
    const std::string& type = prim.prim().typeName;
    Builder local;
    if (type == "Sphere") {
        double radius = nonNegative(prim, "radius", 1.0);
        if (radius > 0.0) lathe(local, capsuleProfile(radius, 0.0, sphereSegments()), sphereSegments(), 'Z');
    } else if (type == "Cube") {
        double size = nonNegative(prim, "size", 2.0);
        if (size > 0.0) cube(local, size);
    } else if (type == "Capsule") {
        double radius = nonNegative(prim, "radius", 0.5);
        double height = nonNegative(prim, "height", 1.0);
        char axis = axisOf(prim);
        if (radius > 0.0) lathe(local, capsuleProfile(radius, height, sphereSegments()), sphereSegments(), axis);
    } else if (type == "Capsule_1") {
        const double top = nonNegative(prim, "radiusTop", 0.5), bottom = nonNegative(prim, "radiusBottom", 0.5);
        const double height = nonNegative(prim, "height", 1.0);
        const char axis = axisOf(prim);
        if (top == bottom && top > 0.0) {
            lathe(local, capsuleProfile(top, height, sphereSegments()), sphereSegments(), axis);
        } else if (top != bottom) {
            if (!(std::abs(top - bottom) < height))
                prim.fail(
                    "the radii of a Capsule_1 must differ by less than its height (one cap would swallow the other)");
            lathe(local, taperedCapsuleProfile(top, bottom, height, sphereSegments()), sphereSegments(), axis);
        }
    } else if (type == "Cylinder" || type == "Cone") {
        const double radius = nonNegative(prim, "radius", 1.0);
        const double height = nonNegative(prim, "height", 2.0);
        const char axis = axisOf(prim);
        if (radius > 0.0) frustum(local, type == "Cone" ? 0.0 : radius, radius, height, axis);
    } else if (type == "Cylinder_1") {
        const double top = nonNegative(prim, "radiusTop", 1.0), bottom = nonNegative(prim, "radiusBottom", 1.0);
        const double height = nonNegative(prim, "height", 2.0);
        if (top > 0.0 || bottom > 0.0) frustum(local, top, bottom, height, axisOf(prim));
    } else if (type == "NurbsPatch") {
        TessellatedSurface patch = tessellateNurbsPatch(prim, warn);
        local.points = std::move(patch.points);
        local.normals = std::move(patch.normals);
        local.indices = std::move(patch.indices);
    } else if (type == "Plane") {
        const double width = nonNegative(prim, "width", 2.0), length = nonNegative(prim, "length", 2.0);
        if (width > 0.0 && length > 0.0) plane(local, width, length, axisOf(prim));
    } else {
        prim.fail("'" + type + "' is not an implicit surface");
    }

    render::MeshDesc mesh;
    mesh.name = prim.path();
    mesh.positions.reserve(local.points.size());
    for (const Vec3d& p : local.points) mesh.positions.emplace_back(toWorld.transformPoint(p));
    std::vector<Vec3f> normals;
    normals.reserve(local.normals.size());
    for (const Vec3d& n : local.normals) {
        Vec3d w = toWorld.transformNormal(n);
        double len = length(w);
        normals.emplace_back(len > 0.0 ? w / len : w);
    }
    const bool mirrored = toWorld.determinant3x3() < 0.0;
    mesh.indices = std::move(local.indices);
    if (mirrored)
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    mesh.cornerNormals.reserve(mesh.indices.size());
    for (std::uint32_t i : mesh.indices) mesh.cornerNormals.push_back(normals[i]);
    if (std::optional<RGB> color = displayColor(prim, convertColor, warn))
        mesh.cornerColors.assign(mesh.indices.size(), *color);
    return mesh;
}

}  // namespace fluence::delegate
