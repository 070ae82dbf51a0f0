// The reflection models before physically based shading, shared by the forward pass's
// fragment shader (flat, Phong, Blinn-Phong) and vertex shader (Gouraud). The includer
// declares the frame and material blocks (frame, material); the lights come from lights/light_list.glsl.
//
// Phong 1975, "Illumination for Computer Generated Pictures": I = ka Ia + kd (N·L) Il +
// ks (R·V)^n Il. Blinn 1977, "Models of Light Reflection for Computer Synthesized Pictures":
// (N·H)^n in place of (R·V)^n. Light intensities are read as illuminance / π (lux / π), so a
// white Phong diffuse surface is exactly as bright as a white Lambertian one under the same
// light, and the models can be compared with the physically based one in one scene.
#include "../common/math.glsl"
#include "../lights/light_list.glsl"
#include "../lights/punctual.glsl"
#include "../lights/shadow.glsl"

// material.phong.a, or when it is 0 the exponent whose Blinn-Phong lobe matches the
// microfacet α = perceptualRoughness² (Walter et al. 2007, eq. 30: n = 2/α² - 2), clamped to
// [1, 8192] so that a mirror stays a finite float.
float classicShininess(float perceptualRoughness)
{
    if (material.phong.a > 0.0) return material.phong.a;
    float alpha = perceptualRoughness * perceptualRoughness;
    return clamp(2.0 / (alpha * alpha) - 2.0, 1.0, 8192.0);
}

// Sums over `list`'s lights of the diffuse factor E (N·L) / π and the specular factor
// E (R·V)^n / π (or (N·H)^n with BLINN), each light's E scaled by its shadow visibility, for
// the caller to weight by kd and ks. The caller finds the list (lightList: the fragment
// shader has gl_FragCoord, the vertex shader does not).
void classicLighting(LightList list, vec3 p, vec3 n, vec3 v, float shininess, bool blinn, out vec3 diffuse, out vec3 specular)
{
    diffuse = vec3(0.0);
    specular = vec3(0.0);
    for (uint k = 0u; k < list.count; ++k) {
        uint index = lightListIndex(list, k);
        vec3 l;
        GpuLight light = lightAt(index);
        vec3 illuminance = lightIlluminance(light, p, l);
        float NoL = dot(n, l);
        if (NoL <= 0.0) continue; // no highlight on the unlit side (Phong 1975)
        illuminance *= shadowVisibility(light, p, n, l);
        float lobe = blinn ? saturate(dot(n, normalize(l + v))) : saturate(dot(reflect(-l, n), v));
        diffuse += illuminance * (NoL * INV_PI);
        specular += illuminance * (pow(lobe, shininess) * INV_PI);
    }
}
