// USDA text for end-to-end tests.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

namespace fluence::test {

// A flat-faceted UV sphere Mesh prim body (points, counts, indices) of radius 1 at the origin.
inline std::string usdSphereMesh(int segments = 48, int rings = 24) {
    const double pi = 3.14159265358979323846;
    std::ostringstream points, counts, indices;
    points.precision(9);
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            double theta = pi * r / rings, phi = 2 * pi * s / segments;
            points << (r || s ? ", " : "") << "(" << std::sin(theta) * std::cos(phi) << ", "
                   << std::sin(theta) * std::sin(phi) << ", " << std::cos(theta) << ")";
        }
    bool first = true;
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            int a = r * (segments + 1) + s, b = a + segments + 1;
            counts << (first ? "" : ", ") << 4;
            indices << (first ? "" : ", ") << a << ", " << b << ", " << b + 1 << ", " << a + 1;
            first = false;
        }
    return "        int[] faceVertexCounts = [" + counts.str() + "]\n        int[] faceVertexIndices = [" +
           indices.str() + "]\n        point3f[] points = [" + points.str() + "]\n";
}

// The white furnace: a diffuse sphere of the given albedo (a UsdPreviewSurface in the specular
// workflow with a black specularColor: exactly Lambertian), a DomeLight of radiance 1, Z up.
inline std::string furnaceUsda(double albedo) {
    std::ostringstream s;
    s << "#usda 1.0\n(\n    upAxis = \"Z\"\n    metersPerUnit = 1\n)\n\n"
      << "def Xform \"World\"\n{\n"
      << "    def Mesh \"Sphere\" (\n        prepend apiSchemas = [\"MaterialBindingAPI\"]\n    )\n    {\n"
      << "        uniform token subdivisionScheme = \"none\"\n"
      << usdSphereMesh() << "        rel material:binding = </World/Looks/Grey>\n    }\n"
      << "    def Scope \"Looks\"\n    {\n        def Material \"Grey\"\n        {\n"
      << "            token outputs:surface.connect = </World/Looks/Grey/Surface.outputs:surface>\n"
      << "            def Shader \"Surface\"\n            {\n"
      << "                uniform token info:id = \"UsdPreviewSurface\"\n"
      << "                color3f inputs:diffuseColor = (" << albedo << ", " << albedo << ", " << albedo << ")\n"
      << "                int inputs:useSpecularWorkflow = 1\n"
      << "                color3f inputs:specularColor = (0, 0, 0)\n"
      << "                token outputs:surface\n            }\n        }\n    }\n"
      << "    def DomeLight \"Dome\"\n    {\n        float inputs:intensity = 1\n    }\n"
      << "    def Camera \"Camera\"\n    {\n        float focalLength = 50\n"
      << "        float horizontalAperture = 36\n        float verticalAperture = 36\n"
      << "        double3 xformOp:translate = (0, -4, 0)\n        float3 xformOp:rotateXYZ = (90, 0, 0)\n"
      << "        uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:rotateXYZ\"]\n    }\n}\n";
    return s.str();
}

// A camera looking at a unit quad whose UsdPreviewSurface takes its diffuse colour from a
// UsdUVTexture of file @textureAsset@ (through an st primvar reader), under a sphere light.
inline std::string texturedQuadUsda(const std::string& textureAsset) {
    return std::string(
        "#usda 1.0\n"
        "(\n"
        "    defaultPrim = \"World\"\n"
        "    metersPerUnit = 1\n"
        "    upAxis = \"Y\"\n"
        ")\n"
        "def Xform \"World\"\n"
        "{\n"
        "    def Camera \"Cam\"\n"
        "    {\n"
        "        double3 xformOp:translate = (0, 0, 5)\n"
        "        uniform token[] xformOpOrder = [\"xformOp:translate\"]\n"
        "    }\n"
        "    def Mesh \"Quad\" (prepend apiSchemas = [\"MaterialBindingAPI\"])\n"
        "    {\n"
        "        int[] faceVertexCounts = [4]\n"
        "        int[] faceVertexIndices = [0, 1, 2, 3]\n"
        "        point3f[] points = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]\n"
        "        texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)] (interpolation = \"vertex\")\n"
        "        rel material:binding = </World/Mat>\n"
        "    }\n"
        "    def Material \"Mat\"\n"
        "    {\n"
        "        token outputs:surface.connect = </World/Mat/PBR.outputs:surface>\n"
        "        def Shader \"PBR\"\n"
        "        {\n"
        "            uniform token info:id = \"UsdPreviewSurface\"\n"
        "            color3f inputs:diffuseColor.connect = </World/Mat/Tex.outputs:rgb>\n"
        "            token outputs:surface\n"
        "        }\n"
        "        def Shader \"Tex\"\n"
        "        {\n"
        "            uniform token info:id = \"UsdUVTexture\"\n"
        "            asset inputs:file = @" +
        textureAsset +
        "@\n"
        "            float2 inputs:st.connect = </World/Mat/St.outputs:result>\n"
        "            float3 outputs:rgb\n"
        "        }\n"
        "        def Shader \"St\"\n"
        "        {\n"
        "            uniform token info:id = \"UsdPrimvarReader_float2\"\n"
        "            token inputs:varname = \"st\"\n"
        "            float2 outputs:result\n"
        "        }\n"
        "    }\n"
        "    def SphereLight \"L\"\n"
        "    {\n"
        "        float inputs:intensity = 10\n"
        "        double3 xformOp:translate = (0, 0, 3)\n"
        "        uniform token[] xformOpOrder = [\"xformOp:translate\"]\n"
        "    }\n"
        "}\n"
        "\n");
}

}  // namespace fluence::test
