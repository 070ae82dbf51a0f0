// Borders of the bloom pyramid (render/BloomPass). Beyond its edges the frame is taken to
// continue as its own mirror image: with symmetric filters, the energy a filter would carry
// out of the image is then exactly what the reflection brings back in, so the glow of a light
// at the edge keeps its energy and its shape (clamping to the edge instead repeats the border
// texel at every level, and such a glow grows several times over; zeros would drain it).
//
// Levels are rounded up (1023 -> 512 -> 256 ...) and map exactly 2:1, so in level k the frame
// ends at size / 2^k texels, which need not be a texel edge: every tap is reflected about that
// point before it samples. Where the frame's end is a texel edge (even sizes) this is the
// exact mirror of GL_MIRRORED_REPEAT, bilinear footprints included.

// A position in texels of a level, reflected about 0 and about `extent` (the frame's end).
vec2 reflectIntoFrame(vec2 position, vec2 extent)
{
    position = abs(position);
    return extent - abs(extent - position);
}
