// Transmission through a surface (KHR_materials_transmission, _ior, _volume) by screen-space
// refraction of the opaque frame (render/passes/ForwardPass: the frame before any transmissive
// or blended surface, resolved, with its mip chain). After the Khronos glTF sample viewer's
// getIBLVolumeRefraction (ibl.glsl there) and Filament's evaluateRefraction: the refracted ray
// leaves the volume `thickness` metres further on, and what the frame shows at that point,
// blurred by roughness, is the light that comes through. Included by pbr.frag with TRANSMISSION.

layout(binding = SPECULA_UNIT_TRANSMISSION) uniform sampler2D uTransmissionFrame;
#if defined(TRANSMISSION_TEXTURES)
// KHR_materials_transmission's texture (R) and KHR_materials_volume's (G): white without one.
layout(binding = SPECULA_UNIT_TRANSMISSION_FACTOR) uniform sampler2D uTransmissionTexture;
layout(binding = SPECULA_UNIT_THICKNESS) uniform sampler2D uThicknessTexture;
#endif
uniform mat4 uModel; // the vertex stage's: the volume's thickness is in object space

// The Khronos sample viewer's applyIorToRoughness: a refraction of ior 1 does not spread a
// ray, whatever the roughness; from ior 1.5 up the full roughness applies.
float transmissionRoughness(float perceptualRoughness, float ior)
{
    return perceptualRoughness * clamp(ior * 2.0 - 2.0, 0.0, 1.0);
}

// Beer–Lambert: light keeps `color` of itself after `distance` metres, so c^(d / distance)
// after d (KHR_materials_volume). distance 0 means infinite: nothing is lost.
vec3 volumeAttenuation(float pathLength, vec3 color, float distance)
{
    if (distance <= 0.0 || pathLength <= 0.0) return vec3(1.0);
    return pow(color, vec3(pathLength / distance));
}

// The light that comes through the surface towards the viewer, before Fresnel and base colour:
// the opaque frame at the refracted ray's exit point, mip level from roughness, attenuated on
// its way through the volume. Where the frame holds nothing (its alpha: the covered fraction,
// when image-based light is on) the environment is seen along the refracted ray instead.
vec3 transmittedRadianceAt(vec3 n, vec3 v, vec3 position, float ior, float thickness, float perceptualRoughness)
{
    vec3 direction = -v;
    vec3 exit = position;
    float pathLength = 0.0;
    if (thickness > 0.0) {
        // A volume: refract into it, leave after `thickness` (scaled as the object is).
        direction = refract(-v, n, 1.0 / ior);
        vec3 modelScale = vec3(length(uModel[0].xyz), length(uModel[1].xyz), length(uModel[2].xyz));
        vec3 path = normalize(direction) * thickness * modelScale;
        pathLength = length(path);
        exit = position + path;
    }
    // Thin-walled (no thickness): both interfaces at once, the ray leaves where it entered, unbent.
    vec4 clip = frame.viewProjection * vec4(exit, 1.0);
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    vec2 size = frame.clusterDepth.zw; // the target's width and height
    float lod = log2(max(size.x, size.y)) * transmissionRoughness(perceptualRoughness, ior);
    vec4 behind = textureLod(uTransmissionFrame, uv, lod);
    vec3 radiance = behind.rgb;
#if defined(IBL)
    // The copy holds radiance × coverage and the coverage (transparency/opaque_copy.frag).
    radiance += (1.0 - behind.a) * prefilteredRadiance(direction, perceptualRoughness) * environment.params.x;
#endif
    return radiance * volumeAttenuation(pathLength, material.attenuation.rgb, material.transmission.w);
}

// KHR_materials_dispersion (DISPERSION variant): red, green and blue refract through the volume
// with their own index of refraction, the extension's linear spread about the material's (its
// green), half of (n_F − n_C) = (ior − 1) / V_d each way, 20 / V_d being the stored value; each
// channel is read along its own ray. Red's index is kept at 1 or above.
vec3 transmittedRadiance(vec3 n, vec3 v, vec3 position, float ior, float thickness, float perceptualRoughness)
{
#if defined(DISPERSION)
    float halfSpread = (ior - 1.0) * 0.025 * material.attenuation.w;
    return vec3(transmittedRadianceAt(n, v, position, max(ior - halfSpread, 1.0), thickness, perceptualRoughness).r,
                transmittedRadianceAt(n, v, position, ior, thickness, perceptualRoughness).g,
                transmittedRadianceAt(n, v, position, ior + halfSpread, thickness, perceptualRoughness).b);
#else
    return transmittedRadianceAt(n, v, position, ior, thickness, perceptualRoughness);
#endif
}
