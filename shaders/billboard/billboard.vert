#version 450 core
// Instanced billboards: six vertices per quad from gl_VertexID, one instance per billboard
// read from a storage buffer. The billboard matrix (right, up, look, position) is built here
// and multiplied by view and projection.
#include "../shared/Bindings.h"
#include "../shared/FrameData.h"
#include "../shared/BillboardData.h"
#include "basis.glsl"
#if defined(DOOM_INDEXED)
#include "../doom/light.glsl"
#endif

layout(std140, binding = SPECULA_BINDING_FRAME) uniform FrameBlock { FrameData frame; };
layout(std430, binding = SPECULA_BINDING_BILLBOARDS) readonly buffer BillboardBuffer { GpuBillboard billboards[]; };

uniform uint uFirstInstance;  // gl_InstanceID starts at 0 in every draw (no gl_BaseInstance in GL 4.5)
uniform uint uKind;           // SPECULA_BILLBOARD_*
uniform vec2 uSize;           // width, height: world units, or pixels when uSizeInPixels
uniform vec2 uAnchor;         // the sprite point at the position, (0, 0) = bottom left
uniform bool uSizeInPixels;
uniform float uViewportHeight;
uniform bool uSpanAxis;       // arbitrary axis: the quad's height is the axis vector (|axis| metres; scene::BillboardGroup::spanAxis)

out vec2 vUv;
out vec3 vTint;
#if defined(DOOM_INDEXED)
// A Doom frame: one colour-map level for the whole sprite, from its sector's light and its
// distance, as Doom lit its things (r_things.c: one colormap per vissprite).
flat out uint vDoomLevel;
#endif

// Two counter-clockwise triangles seen from +Z (the camera side).
const vec2 kCorners[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));

void main()
{
    GpuBillboard b = billboards[uFirstInstance + uint(gl_InstanceID)];
    vec3 position = b.positionScale.xyz;
    vec3 camera = frame.cameraPosition.xyz;
    // The camera's up in world space: the second row of the view rotation (its inverse is its transpose).
    vec3 cameraUp = vec3(frame.view[0][1], frame.view[1][1], frame.view[2][1]);

    mat3 basis;
    if (uKind == SPECULA_BILLBOARD_AXIS_ALIGNED) basis = axisAlignedBasis(position, camera, cameraUp);
    else if (uKind == SPECULA_BILLBOARD_ARBITRARY_AXIS) basis = arbitraryAxisBasis(position, camera, cameraUp, b.axis.xyz);
    else basis = pointSpriteBasis(position, camera, cameraUp);

    vec2 uv = kCorners[gl_VertexID];
    vec2 local = (uv - uAnchor) * uSize * b.positionScale.w;
    if (uSpanAxis) local.y = (uv.y - uAnchor.y) * length(b.axis.xyz);
    if (uSizeInPixels) {
        // A pixel spans 2w / (P[1][1] * height) world units at clip w (render::worldUnitsPerPixel);
        // 0 behind the camera so the quad collapses there instead of flipping towards the viewer.
        // A quad spanning its axis is measured where this vertex is along it, so a rod keeps its
        // width in pixels from end to end; others at their position, keeping their shape.
        vec3 at = uSpanAxis ? position + basis[1] * local.y : position;
        float w = (frame.viewProjection * vec4(at, 1.0)).w;
        float pixel = 2.0 * max(w, 0.0) / (frame.projection[1][1] * uViewportHeight);
        local.x *= pixel;
        if (!uSpanAxis) local.y *= pixel;
    }
    mat4 model = mat4(vec4(basis[0], 0.0), vec4(basis[1], 0.0), vec4(basis[2], 0.0), vec4(position, 1.0));
    vUv = uv;
    vTint = b.tint.rgb;
#if defined(DOOM_INDEXED)
    // Things: the walls' table at their depth (r_things.c, R_ProjectSprite: xscale = projection / tz).
    vDoomLevel = doomWallLevel(b.tint.w * 255.0, -(frame.view * vec4(position, 1.0)).z, 0);
#endif
    gl_Position = frame.projection * (frame.view * (model * vec4(local, 0.0, 1.0)));
}
