#include "scene/Animation.h"

#include <algorithm>
#include <cmath>

namespace specula::scene {

int animatedFieldComponents(AnimatedField field)
{
    switch (field) {
    case AnimatedField::BaseColor: return 4;
    case AnimatedField::Emissive:
    case AnimatedField::SpecularColor:
    case AnimatedField::SheenColor:
    case AnimatedField::DiffuseTransmissionColor:
    case AnimatedField::AttenuationColor:
    case AnimatedField::LightColor: return 3;
    case AnimatedField::TextureOffset:
    case AnimatedField::TextureScale: return 2;
    default: return 1;
    }
}

bool isMaterialField(AnimatedField field)
{
    return field < AnimatedField::LightColor;
}

bool isLightField(AnimatedField field)
{
    return field >= AnimatedField::LightColor && field <= AnimatedField::SpotOuterConeAngle;
}

bool isCameraField(AnimatedField field)
{
    return field >= AnimatedField::CameraYfov && field <= AnimatedField::CameraYmag;
}

bool isNodeField(AnimatedField field)
{
    return field == AnimatedField::NodeVisible;
}

float Animation::duration() const
{
    float end = 0.0f;
    for (const AnimationSampler& s : samplers)
        if (!s.times.empty()) end = std::max(end, s.times.back());
    return end;
}

glm::quat slerpShortest(glm::quat a, glm::quat b, float s)
{
    float d = glm::dot(a, b);
    // q and -q are the same rotation: go the shorter way round.
    if (d < 0.0f) {
        b = -b;
        d = -d;
    }
    glm::quat q;
    if (d > 0.9995f) {
        // Nearly the same rotation: sin(theta) -> 0 makes slerp's weights ill-conditioned, and
        // there linear interpolation differs from it by less than float precision after normalising.
        q = a * (1.0f - s) + b * s;
    } else {
        const float theta = std::acos(d);
        const float sinTheta = std::sin(theta);
        q = a * (std::sin((1.0f - s) * theta) / sinTheta) + b * (std::sin(s * theta) / sinTheta);
    }
    return glm::normalize(q);
}

namespace {

/// Keyframe `k`'s value (component `c`), whatever the layout.
float value(const AnimationSampler& s, size_t k, int c)
{
    const size_t n = size_t(s.components);
    if (s.interpolation == Interpolation::CubicSpline) return s.values[(3 * k + 1) * n + size_t(c)];
    return s.values[k * n + size_t(c)];
}

void normaliseRotation(float* out)
{
    const float length = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2] + out[3] * out[3]);
    if (length > 0.0f && std::isfinite(length))
        for (int c = 0; c < 4; ++c) out[c] /= length;
}

} // namespace

void evaluateSampler(const AnimationSampler& s, float t, bool rotation, float* out)
{
    const int n = s.components;
    const size_t count = s.times.size();
    if (count == 0 || n <= 0) return;
    auto copyKey = [&](size_t k) {
        for (int c = 0; c < n; ++c) out[c] = value(s, k, c);
    };
    if (count == 1 || !(t > s.times.front())) {
        copyKey(0);
    } else if (t >= s.times.back()) {
        copyKey(count - 1);
    } else {
        // k: the last keyframe at or before t (t lies strictly inside the keyframes here).
        const size_t k = size_t(std::upper_bound(s.times.begin(), s.times.end(), t) - s.times.begin()) - 1;
        const float t0 = s.times[k], t1 = s.times[k + 1];
        const float td = t1 - t0;
        const float u = (t - t0) / td;
        switch (s.interpolation) {
        case Interpolation::Step: copyKey(k); break;
        case Interpolation::Linear:
            if (rotation) {
                const glm::quat a(value(s, k, 3), value(s, k, 0), value(s, k, 1), value(s, k, 2));
                const glm::quat b(value(s, k + 1, 3), value(s, k + 1, 0), value(s, k + 1, 1), value(s, k + 1, 2));
                const glm::quat q = slerpShortest(a, b, u);
                out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
            } else {
                for (int c = 0; c < n; ++c) out[c] = value(s, k, c) * (1.0f - u) + value(s, k + 1, c) * u;
            }
            break;
        case Interpolation::CubicSpline: {
            // glTF 2.0 spec, Appendix C (cubic spline): Hermite basis with the tangents scaled by
            // the keyframe delta td; b_k is keyframe k's out-tangent, a_k+1 keyframe k+1's in-tangent.
            const float u2 = u * u, u3 = u2 * u;
            const float h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
            const size_t stride = size_t(n);
            for (int c = 0; c < n; ++c) {
                const float v0 = s.values[(3 * k + 1) * stride + size_t(c)];
                const float b0 = s.values[(3 * k + 2) * stride + size_t(c)];
                const float v1 = s.values[(3 * (k + 1) + 1) * stride + size_t(c)];
                const float a1 = s.values[(3 * (k + 1)) * stride + size_t(c)];
                out[c] = h00 * v0 + td * h10 * b0 + h01 * v1 + td * h11 * a1;
            }
            break;
        }
        }
    }
    if (rotation && n == 4) normaliseRotation(out);
}

} // namespace specula::scene
