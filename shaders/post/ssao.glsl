// View-space positions from the pre-pass depth buffer, shared by the SSAO passes. The includer
// declares the `ssao` block (SsaoData) and the depth sampler uDepth.

// The view-space position at pixel p with depth-buffer value `depth` (GL's [0, 1] window depth,
// the default glClipControl), through the inverse projection, so perspective and orthographic
// cameras both work.
vec3 viewPosition(ivec2 p, float depth)
{
    vec2 ndc = (vec2(p) + 0.5) * ssao.size.zw * 2.0 - 1.0;
    vec4 v = ssao.inverseProjection * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    return v.xyz / v.w;
}

vec3 viewPositionAt(ivec2 p)
{
    return viewPosition(p, texelFetch(uDepth, p, 0).r);
}
