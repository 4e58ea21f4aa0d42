#include "render/curve_primvars.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <stdexcept>

namespace fluence::render {

void validateCurvePrimvars(const CurvesDesc& curves, std::size_t controlPoints, std::size_t segments) {
    for (const CurvePrimvar& pv : curves.primvars) {
        const std::size_t values = pv.perSegment ? 2 * segments : controlPoints;
        if (pv.components < 1 || pv.components > 4 || pv.values.size() != values * std::size_t(pv.components))
            throw std::invalid_argument(curves.name + ": primvar " + pv.name + " needs 1 to 4 values per " +
                                        (pv.perSegment ? "segment end" : "control point"));
    }
}

CurveShading::CurveShading(const CurvesDesc& curves, const MaterialShader& shader, unsigned firstAttribute)
    : shader_(&shader) {
    const std::vector<std::string>& names = shader.primvarSlots();
    primvars_.reserve(std::min(names.size(), kMaxCurvePrimvarSlots));  // Slot::primvar points into it
    for (std::size_t s = 0; s < names.size(); ++s) {
        Slot slot;
        auto byName = [&](const CurvePrimvar& pv) { return !names[s].empty() && pv.name == names[s]; };
        const auto found = std::find_if(curves.primvars.begin(), curves.primvars.end(), byName);
        if (s < kMaxCurvePrimvarSlots && found != curves.primvars.end()) {
            const auto earlier = std::find_if(slots_.begin(), slots_.end(),
                                              [&](const Slot& e) { return e.primvar && byName(*e.primvar); });
            if (earlier != slots_.end()) {
                slot = *earlier;
            } else {
                primvars_.push_back(*found);
                slot.primvar = &primvars_.back();
                if (!found->perSegment) {
                    slot.attribute = firstAttribute + attributeCount();
                    attributes_.push_back(slot.attribute);
                    perControlPoint_.push_back(slot.primvar);
                }
            }
        }
        slots_.push_back(slot);
        heads_.push_back(slot.primvar ? CornerPrimvar{found->name, found->components, {}} : CornerPrimvar{});
    }
    for (std::size_t s = 0; s < slots_.size(); ++s) slotPointers_.push_back(slots_[s].primvar ? &heads_[s] : nullptr);
}

void CurveShading::setAttributes(RTCGeometry geometry) const {
    for (std::size_t i = 0; i < attributes_.size(); ++i) {
        const CurvePrimvar& pv = *perControlPoint_[i];
        const auto k = static_cast<std::size_t>(pv.components);
        const auto format = static_cast<RTCFormat>(RTC_FORMAT_FLOAT + pv.components - 1);
        auto* values =
            static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, attributes_[i],
                                                        format, k * sizeof(float), pv.values.size() / k));
        std::copy(pv.values.begin(), pv.values.end(), values);
    }
}

void CurveShading::evaluate(RTCGeometry geometry, unsigned segment, float u, MaterialParams& out) const {
    float values[kMaxCurvePrimvarSlots][4];
    for (std::size_t s = 0; s < slots_.size(); ++s) {
        const CurvePrimvar* pv = slots_[s].primvar;
        if (!pv) continue;
        const auto k = static_cast<std::size_t>(pv->components);
        if (pv->perSegment) {
            const float* ends = pv->values.data() + 2 * k * segment;
            for (std::size_t c = 0; c < k; ++c) values[s][c] = ends[c] * (1.0f - u) + ends[k + c] * u;
            continue;
        }
        RTCInterpolateArguments args{};
        args.geometry = geometry;
        args.primID = segment;
        args.u = u;
        args.bufferType = RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE;
        args.bufferSlot = slots_[s].attribute;
        args.P = values[s];
        args.valueCount = static_cast<unsigned>(k);
        rtcInterpolate(&args);
    }
    ShadingPatch patch;
    patch.atPoint = values;
    Vec3f normal(0.0f, 0.0f, 1.0f), tangent;  // curves take no normal map (see the header)
    shader_->evaluate(patch, slotPointers_.data(), out, normal, tangent);
}

}  // namespace fluence::render
