// View-space geometry from the pre-pass's buffer (rgb the view-space face normal, a the
// view-space z; a > 0 where nothing was drawn), shared by the SSAO passes. The includer
// declares the `ssao` block (SsaoData) and the sampler uGeometry. One fetch gives position and
// normal: no depth-buffer read and no inverse projection per sample.

bool nothingAt(vec4 geometry)
{
    return geometry.w > 0.0; // view space looks down -z: everything drawn has z < 0
}

// The view-space position seen at pixel p at view depth z: the projection solved for x and y
// (it has no skew and w = P[2][3] z + P[3][3]: -z for a perspective, 1 for an orthographic one).
vec3 viewPosition(ivec2 p, float z)
{
    mat4 P = ssao.projection;
    vec2 ndc = (vec2(p) + 0.5) * ssao.size.zw * 2.0 - 1.0;
    float w = P[2][3] * z + P[3][3];
    return vec3((ndc.x * w - P[2][0] * z - P[3][0]) / P[0][0], (ndc.y * w - P[2][1] * z - P[3][1]) / P[1][1], z);
}

// The view-space depth where the line of sight through `s` (a point in view space) meets the
// surface seen at pixel q, taken as the plane through its position with its normal. Comparing
// `s` against the depth at q's centre instead would be off by the depth change across part of
// a pixel, which on a surface seen at a grazing angle is far more than the bias: the surface
// would occlude itself. At a silhouette q keeps its own surface (no blend of two depths).
float surfaceDepthAlong(vec3 s, vec3 qPosition, vec3 qNormal)
{
    if (ssao.options.x > 0.0) {
        // Orthographic: lines of sight run along -z.
        if (abs(qNormal.z) < 1e-4) return qPosition.z;
        return s.z + dot(qNormal, qPosition - s) / qNormal.z;
    }
    // Perspective: the line of sight is the ray from the eye (the origin) through s.
    float d = dot(qNormal, s);
    if (abs(d) < 1e-6) return qPosition.z; // the ray runs along the plane
    return s.z * dot(qNormal, qPosition) / d;
}
