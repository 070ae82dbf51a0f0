// Tone mapping operators; input is exposed scene-referred linear RGB.

// Reinhard et al. 2002, "Photographic Tone Reproduction for Digital Images", eq. 3, per channel.
vec3 tonemapReinhard(vec3 c)
{
    return c / (1.0 + c);
}

// Reinhard 2002, eq. 4, on luminance with white point Lw (the smallest luminance mapped to 1).
vec3 tonemapReinhardExtended(vec3 c, float whitePoint)
{
    float l = luminance(c);
    if (l <= 0.0) return vec3(0.0);
    float mapped = l * (1.0 + l / (whitePoint * whitePoint)) / (1.0 + l);
    return c * (mapped / l);
}

// ACES filmic, Stephen Hill's fit of the RRT + ODT (BakingLab, 2016): sRGB -> AP1-ish,
// rational fit, back to sRGB.
vec3 tonemapAces(vec3 c)
{
    const mat3 inputMatrix = mat3(0.59719, 0.07600, 0.02840, 0.35458, 0.90834, 0.13383, 0.04823, 0.01566, 0.83777);
    const mat3 outputMatrix = mat3(1.60475, -0.10208, -0.00327, -0.53108, 1.10813, -0.07276, -0.07367, -0.00605, 1.07602);
    c = inputMatrix * c;
    vec3 a = c * (c + 0.0245786) - 0.000090537;
    vec3 b = c * (0.983729 * c + 0.4329510) + 0.238081;
    return clamp(outputMatrix * (a / b), 0.0, 1.0);
}

// Khronos PBR Neutral tone mapper (Khronos 3D Commerce, 2024): identity below 0.76,
// then a hue-preserving highlight roll-off with a little desaturation.
vec3 tonemapNeutral(vec3 c)
{
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    float x = min(c.r, min(c.g, c.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    c -= offset;
    float peak = max(c.r, max(c.g, c.b));
    if (peak < startCompression) return c;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    c *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return mix(c, vec3(newPeak), g);
}

// AgX (Troy Sobotka, 2022), in Benjamin Wrensch's minimal form ("Minimal AgX Implementation",
// 2023): the inset matrix, a log2 encoding over [-12.47, +4.03] stops around 0.18, a 6th-order
// polynomial fit of AgX's default contrast sigmoid, the outset matrix, and the 2.2 display
// EOTF so the result is linear again for our sRGB target. Bright saturated colours desaturate
// towards white instead of clipping to a hue-shifted primary.
vec3 agxContrastApprox(vec3 x)
{
    vec3 x2 = x * x;
    vec3 x4 = x2 * x2;
    return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
}

vec3 tonemapAgx(vec3 c)
{
    const mat3 inset = mat3(0.842479062253094, 0.0423282422610123, 0.0423756549057051,
                            0.0784335999999992, 0.878468636469772, 0.0784336,
                            0.0792237451477643, 0.0791661274605434, 0.879142973793104);
    const mat3 outset = mat3(1.19687900512017, -0.0528968517574562, -0.0529716355144438,
                             -0.0980208811401368, 1.15190312990417, -0.0980434501171241,
                             -0.0990297440797205, -0.0989611768448433, 1.15107367264116);
    const float minEv = -12.47393, maxEv = 4.026069;
    // 1e-10: log2(0) is -Inf; anything below 2^minEv maps to the same black anyway.
    c = clamp(log2(max(inset * c, vec3(1e-10))), minEv, maxEv);
    c = agxContrastApprox((c - minEv) / (maxEv - minEv));
    // The polynomial dips just below 0 at black: clamp before the power.
    return pow(max(outset * c, vec3(0.0)), vec3(2.2));
}

vec3 tonemap(vec3 c, uint op, float whitePoint)
{
    if (op == SPECULA_TONEMAP_AGX) return tonemapAgx(c);
    if (op == SPECULA_TONEMAP_REINHARD) return tonemapReinhard(c);
    if (op == SPECULA_TONEMAP_REINHARD_EXT) return tonemapReinhardExtended(c, whitePoint);
    if (op == SPECULA_TONEMAP_ACES) return tonemapAces(c);
    if (op == SPECULA_TONEMAP_NEUTRAL) return tonemapNeutral(c);
    return c;
}
