#pragma once
// The Doom model's demo level (`specula render doom`): a few connected sectors with their own
// light levels, spread between them (scene/DoomLighting.h), textured with small procedural
// textures in palette colours (scene/DoomPalette.h), and a few things (lamps, barrels) drawn as
// cutout sprites lit by their sector, as Doom drew them.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/DoomLighting.h"
#include "scene/Scene.h"

namespace specula::scene::doom {

/// The level's textures, each kTextureSize² texels of palette colours made here in code.
enum class LevelTexture { Bricks, Stone, Wood, Flagstones, Ceiling, Moss, Count };
constexpr int kTextureSize = 64; ///< texels, as Doom's flats: one texel a map unit

/// A texture as palette indices, kTextureSize² of them, top row first.
std::vector<uint8_t> makeTextureIndices(LevelTexture texture);
/// The same as an RGBA image (sRGB palette colours, alpha 255).
Image makeTextureImage(LevelTexture texture);

/// A thing of the level (Doom's THINGS): a sprite standing on the floor.
enum class ThingKind { Lamp, Barrel };
struct Thing {
    ThingKind kind;
    glm::ivec2 position; ///< x, z in map units
};
/// A thing's sprite: palette colours where alpha is 255, alpha 0 around them (cutout).
Image makeSpriteImage(ThingKind kind);

/// A sector of the demo level (map units: 32 a metre).
struct LevelSector {
    Sector sector;
    int floor = 0, ceiling = 128; ///< heights, map units
    LevelTexture floorTexture = LevelTexture::Flagstones, wallTexture = LevelTexture::Stone,
                 ceilingTexture = LevelTexture::Ceiling;
};
std::vector<LevelSector> demoLevelSectors();
std::vector<Thing> demoLevelThings();
/// The light attenuation per sector crossed in the demo level (spreadLight).
constexpr int kDemoLevelAttenuation = 64;

/// The demo level: a lit start room, a corridor, a hall, a dark side room and a nook, their
/// light spread with kDemoLevelAttenuation, as floors, ceilings and walls of Doom-model
/// materials with the level's textures; its things as axis-aligned cutout billboards (lamps
/// full bright, barrels at their sector's light) with a point light at each lamp (for the
/// other shading models; the Doom model ignores lights); and a camera in the start room
/// looking down the corridor.
Scene makeDemoLevel();

} // namespace specula::scene::doom
