#version 450 core
// Screen-space ambient occlusion, Crytek's idea (Mittring 2007, "Finding Next Gen: CryEngine
// 2") in the normal-oriented hemisphere form of LearnOpenGL's "SSAO" (de Vries 2014): sample
// points in a hemisphere of `radius` metres around the surface normal, project each to the
// screen and count those lying behind the depth buffer. A 4x4 noise texture rotates the kernel
// per pixel (the blur pass averages the 16 rotations away); a range check fades occluders
// much nearer the camera than the radius, so an object does not darken the far background
// around its silhouette (no halos).
#include "../shared/Bindings.h"
#include "../shared/PostData.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = SPECULA_BINDING_SSAO) uniform SsaoBlock { SsaoData ssao; };
layout(binding = SPECULA_UNIT_POST_INPUT) uniform sampler2D uGeometry; // view normal, view z
layout(binding = SPECULA_UNIT_POST_INPUT_2) uniform sampler2D uNoise;
layout(binding = SPECULA_IMAGE_POST_OUTPUT, r16f) uniform writeonly image2D uOcclusion;

#include "ssao.glsl"

void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(ssao.size.xy);
    if (any(greaterThanEqual(p, size))) return;
    vec4 geometry = texelFetch(uGeometry, p, 0);
    // Nothing drawn here: nothing to occlude.
    if (nothingAt(geometry)) {
        imageStore(uOcclusion, p, vec4(1.0));
        return;
    }
    vec3 position = viewPosition(p, geometry.w);
    vec3 n = geometry.xyz;
    vec3 random = vec3(texelFetch(uNoise, p % SPECULA_SSAO_NOISE_SIZE, 0).xy, 0.0);
    // Gram-Schmidt: a tangent from the random vector, unless it is nearly the normal itself.
    vec3 t = random - n * dot(random, n);
    if (dot(t, t) < 1e-4) t = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) - n * n.x : vec3(0.0, 1.0, 0.0) - n * n.y;
    t = normalize(t);
    mat3 tbn = mat3(t, cross(n, t), n);

    float radius = ssao.params.x, bias = ssao.params.y;
    int count = int(ssao.params.w);
    float occluded = 0.0;
    for (int i = 0; i < count; ++i) {
        vec3 s = position + tbn * ssao.kernel[i].xyz * radius;
        vec4 clip = ssao.projection * vec4(s, 1.0);
        if (clip.w <= 0.0) continue; // behind the camera: cannot be tested, counts as open
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        // Off screen there is no depth to test against: counts as open, so borders never
        // darken for lack of information.
        if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) continue;
        ivec2 q = ivec2(uv * ssao.size.xy);
        vec4 qGeometry = texelFetch(uGeometry, q, 0);
        if (nothingAt(qGeometry)) continue; // nothing drawn there: nothing occludes
        float sceneZ = surfaceDepthAlong(s, viewPosition(q, qGeometry.w), qGeometry.xyz);
        // View space looks down -z: the sample is hidden when the surface there is nearer.
        float hidden = sceneZ >= s.z + bias ? 1.0 : 0.0;
        // Range check: an occluder far in front of this point (another object) counts less
        // and less, rather than casting a halo onto what lies behind it.
        float range = smoothstep(0.0, 1.0, radius / max(abs(position.z - sceneZ), 1e-6));
        occluded += hidden * range;
    }
    float ao = 1.0 - occluded / float(max(count, 1));
    imageStore(uOcclusion, p, vec4(pow(ao, ssao.params.z)));
}
