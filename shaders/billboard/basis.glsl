// Billboard bases on the GPU: one function per kind, each returning the columns right, up,
// look of a right-handed orthonormal frame (right x up = look). The same formulas and
// fallbacks as render::billboardMatrix (src/shading/Billboard.cpp); keep the two equal.

// Two unit vectors with sin^2 of their angle below 1e-6 (0.06 degrees) count as parallel:
// below that their cross product's direction is mostly rounding and would flicker.
const float kBillboardParallel = 1e-6;
// A camera closer than 1 micrometre to the position gives no usable direction.
const float kBillboardMinLength2 = 1e-12;

vec3 billboardNormalizeOr(vec3 v, vec3 fallback)
{
    float length2 = dot(v, v);
    return length2 > kBillboardMinLength2 ? v * inversesqrt(length2) : fallback;
}

// A unit vector perpendicular to unit n (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited", JCGT 6(1), listing 3).
vec3 billboardPerpendicular(vec3 n)
{
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    return vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
}

// Point sprite: turns about its centre to face the camera, keeping the camera's up.
//   look = normalize(camera - position)
//   right = normalize(cross(cameraUp, look))
//   up' = cross(look, right)
// Look parallel to cameraUp (the sprite 90 degrees off the view axis, outside any perspective
// frustum): any steady perpendicular for right.
mat3 pointSpriteBasis(vec3 position, vec3 camera, vec3 cameraUp)
{
    vec3 look = billboardNormalizeOr(camera - position, vec3(0.0, 0.0, 1.0));
    vec3 up0 = billboardNormalizeOr(cameraUp, vec3(0.0, 1.0, 0.0));
    vec3 right = cross(up0, look);
    right = dot(right, right) >= kBillboardParallel ? normalize(right) : billboardPerpendicular(look);
    return mat3(right, cross(look, right), look);
}

// Axis-aligned: turns about world +Y only.
//   look = normalize((camera - position) with y = 0)
//   right = cross(Y, look), up = Y
// Camera straight above or below: look away from the camera's up (flattened), which is where
// the look came from for a camera tilting over the pole; if that is vertical too, +Z.
mat3 axisAlignedBasis(vec3 position, vec3 camera, vec3 cameraUp)
{
    vec3 look0 = billboardNormalizeOr(camera - position, vec3(0.0, 0.0, 1.0));
    vec3 flattened = vec3(look0.x, 0.0, look0.z);
    if (dot(flattened, flattened) < kBillboardParallel) {
        vec3 away = -billboardNormalizeOr(cameraUp, vec3(0.0, 0.0, 1.0));
        flattened = vec3(away.x, 0.0, away.z);
        if (dot(flattened, flattened) < kBillboardParallel) flattened = vec3(0.0, 0.0, 1.0);
    }
    vec3 look = normalize(flattened);
    vec3 up = vec3(0.0, 1.0, 0.0);
    return mat3(cross(up, look), up, look);
}

// Arbitrary axis A: turns about A only.
//   right = normalize(cross(A, look)), look' = cross(right, A), up = A
// Looking along A: right from -cameraUp as for the axis-aligned case; if the camera's up is
// along A as well, any steady perpendicular.
mat3 arbitraryAxisBasis(vec3 position, vec3 camera, vec3 cameraUp, vec3 axis)
{
    vec3 a = billboardNormalizeOr(axis, vec3(0.0, 1.0, 0.0));
    vec3 look0 = billboardNormalizeOr(camera - position, vec3(0.0, 0.0, 1.0));
    vec3 right = cross(a, look0);
    if (dot(right, right) < kBillboardParallel) {
        right = cross(a, -billboardNormalizeOr(cameraUp, vec3(0.0, 0.0, 1.0)));
        if (dot(right, right) < kBillboardParallel) right = billboardPerpendicular(a);
    }
    right = normalize(right);
    return mat3(right, a, cross(right, a));
}
