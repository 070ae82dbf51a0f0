// How much of light `lightIndex` reaches a shading point, in [0, 1]: 0 in its shadow, 1 in
// full light. Every reflection model multiplies each light's contribution by it, so shadows
// come in here and nowhere else. `normal` is for a normal-offset bias (Holbein 2011,
// "Normal Offset Shadows"), `lightIndex` selects the light's shadow map.
//
// No light casts shadows yet: exactly 1.0, so images do not change (x * 1.0 == x in IEEE 754).
float shadowVisibility(uint lightIndex, vec3 worldPosition, vec3 normal)
{
    return 1.0;
}
