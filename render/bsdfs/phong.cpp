#include "render/bsdfs/phong.h"

#include "core/frame.h"
#include "render/bsdfs/power_cosine.h"

namespace fluence::render {

Vec3f PhongLobe::sample(const Vec3f& wo, Vec2f u, float n) {
    return Frame::fromNormal(mirrorZ(-wo)).toWorld(samplePowerCosine(u, n));
}

float PhongLobe::pdf(const Vec3f& wo, const Vec3f& wi, float n) { return powerCosinePdf(cosine(wo, wi), n); }

}  // namespace fluence::render
