#include "delegate/xform.h"

#include <string_view>

namespace fluence::delegate {

namespace {

Matrix4 rotationFromOrder(std::string_view order, const Vec3d& angles) {
    // angles are authored (x, y, z); `order` lists the axes in the order they apply to a point.
    Matrix4 m = Matrix4::identity();
    for (char axis : order) {
        Matrix4 r = axis == 'X'   ? Matrix4::rotateX(angles.x)
                    : axis == 'Y' ? Matrix4::rotateY(angles.y)
                                  : Matrix4::rotateZ(angles.z);
        m = r * m;
    }
    return m;
}

Matrix4 opMatrix(const PrimReader& prim, const std::string& attributeName) {
    std::string_view rest(attributeName);
    rest.remove_prefix(std::string_view("xformOp:").size());
    std::string_view type = rest.substr(0, rest.find(':'));
    const std::optional<usd::Value> v = prim.value(attributeName);  // localTransform checked it has one
    if (!v->isNumeric()) prim.fail("xform op '" + attributeName + "' is not numeric: " + v->toString());
    const std::vector<double>& n = v->numbers;
    auto need = [&](std::size_t count) {
        if (n.size() != count)
            prim.fail("xform op '" + attributeName + "' needs " + std::to_string(count) + " numbers, got " +
                      v->toString());
    };
    if (type == "translate") {
        need(3);
        return Matrix4::translate({n[0], n[1], n[2]});
    }
    if (type == "scale") {
        need(3);
        return Matrix4::scale({n[0], n[1], n[2]});
    }
    if (type == "rotateX" || type == "rotateY" || type == "rotateZ") {
        need(1);
        return type == "rotateX"   ? Matrix4::rotateX(n[0])
               : type == "rotateY" ? Matrix4::rotateY(n[0])
                                   : Matrix4::rotateZ(n[0]);
    }
    if (type.size() == 9 && type.starts_with("rotate")) {
        std::string_view order = type.substr(6);
        bool valid = order.find('X') != order.npos && order.find('Y') != order.npos && order.find('Z') != order.npos;
        if (valid) {
            need(3);
            return rotationFromOrder(order, {n[0], n[1], n[2]});
        }
    }
    if (type == "orient") {
        need(4);
        return Matrix4::fromQuaternion(n[0], n[1], n[2], n[3]);
    }
    if (type == "transform") {
        need(16);
        return Matrix4::fromUsdRowMajor(n.data());
    }
    prim.fail("unknown xform op type '" + std::string(type) + "' in '" + attributeName + "'");
}

}  // namespace

LocalTransform localTransform(const PrimReader& prim, const std::function<void(const std::string&)>& warn) {
    LocalTransform result;
    std::optional<std::vector<std::string>> order = prim.strings("xformOpOrder");
    if (!order) return result;
    for (const std::string& entry : *order) {
        if (entry == "!resetXformStack!") {
            result.matrix = Matrix4::identity();
            result.resetsXformStack = true;
            continue;
        }
        constexpr std::string_view kInvert = "!invert!";
        bool invert = entry.starts_with(kInvert);
        std::string name = invert ? entry.substr(kInvert.size()) : entry;
        if (!name.starts_with("xformOp:")) prim.fail("xformOpOrder entry '" + entry + "' is not an xform op");
        if (!prim.value(name)) {
            warn("xformOpOrder names '" + name + "', which has no value; the op is skipped, as USD skips it");
            continue;
        }
        Matrix4 m = opMatrix(prim, name);
        if (invert) {
            std::optional<Matrix4> inv = m.inverse();
            if (!inv) prim.fail("xform op '" + entry + "' cannot be inverted (singular)");
            m = *inv;
        }
        result.matrix = result.matrix * m;
    }
    return result;
}

}  // namespace fluence::delegate
