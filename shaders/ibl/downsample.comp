#version 450 core
// One box-filtered mip of a cube map: each texel of level L the mean of the 2 x 2 texels of
// level L - 1 under it (the bake's cubes, power-of-two faces). What glGenerateMipmap computes,
// as a compute program: llvmpipe's mipmap generation builds blit shaders at each launch (75-79
// ms for a 256² preview's cube), a program the driver's shader cache keeps.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform readonly imageCube uSource;  // level L - 1
layout(binding = 1, rgba16f) uniform writeonly imageCube uTarget; // level L

void main()
{
    ivec3 id = ivec3(gl_GlobalInvocationID);
    int size = imageSize(uTarget).x;
    if (id.x >= size || id.y >= size) return;
    ivec2 p = id.xy * 2;
    vec4 sum = imageLoad(uSource, ivec3(p, id.z)) + imageLoad(uSource, ivec3(p + ivec2(1, 0), id.z)) +
               imageLoad(uSource, ivec3(p + ivec2(0, 1), id.z)) + imageLoad(uSource, ivec3(p + ivec2(1, 1), id.z));
    imageStore(uTarget, id, sum * 0.25);
}
