// The sheen lobe of KHR_materials_sheen: the "Charlie" distribution and its visibility, from
// Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF" (eq. 2 and the fitted
// shadowing of its section 3), as the extension's implementation notes give them;
// alpha = sheen perceptual roughness^2. f_sheen = sheenColor D_Charlie V_Charlie (F = 1).
#include "../common/math.glsl"

// An exponentiated sine around the normal, normalised so that its projected area is 1:
// (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi).
float D_Charlie(float NoH, float alpha)
{
    float invAlpha = 1.0 / alpha;
    float sin2h = max(1.0 - NoH * NoH, 0.0);
    return (2.0 + invAlpha) * pow(sin2h, 0.5 * invAlpha) / (2.0 * PI);
}

// The paper's fit of ln Lambda(cos theta), its five parameters interpolated between the fits at
// alpha = 0 and alpha = 1 by (1 - alpha)^2.
float charlieL(float x, float alpha)
{
    float t = (1.0 - alpha) * (1.0 - alpha);
    float a = mix(21.5473, 25.3245, t);
    float b = mix(3.82987, 3.32435, t);
    float c = mix(0.19823, 0.16801, t);
    float d = mix(-1.97760, -1.27393, t);
    float e = mix(-4.32054, -4.85967, t);
    return a / (1.0 + b * pow(x, c)) + d * x + e;
}

// Lambda: the fit below cos theta = 0.5, mirrored above it (the paper's "softened" form, which
// keeps the terminator smooth).
float charlieLambda(float cosTheta, float alpha)
{
    return cosTheta < 0.5 ? exp(charlieL(cosTheta, alpha)) : exp(2.0 * charlieL(0.5, alpha) - charlieL(1.0 - cosTheta, alpha));
}

// V = G / (4 n.v n.l) with the height-correlated G = 1 / (1 + Lambda(v) + Lambda(l)).
float V_Charlie(float NoV, float NoL, float alpha)
{
    return 1.0 / ((1.0 + charlieLambda(NoV, alpha) + charlieLambda(NoL, alpha)) * (4.0 * NoV * NoL));
}

// Half vector around +Z distributed as D_Charlie(h) (n.h). With s = sin theta_h that density is
// (2 + 1/alpha) s^(1 + 1/alpha) ds dphi / (2 pi), whose CDF in s is s^(2 + 1/alpha): s = xi^(alpha / (2 alpha + 1)).
vec3 importanceSampleCharlie(vec2 xi, float alpha)
{
    float phi = 2.0 * PI * xi.x;
    float sinTheta = pow(xi.y, alpha / (2.0 * alpha + 1.0));
    float cosTheta = sqrt(max(1.0 - sinTheta * sinTheta, 0.0));
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}
