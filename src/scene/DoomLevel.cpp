#include "scene/DoomLevel.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>
#include <string_view>

#include <glm/gtc/quaternion.hpp>

#include "scene/DemoScenes.h"
#include "scene/Procedural.h"

namespace specula::scene::doom {
namespace {

/// A ramp of the palette by name: its first index and length.
struct RampRef {
    int first = 0, count = 0;
    /// Shade k of the ramp (0 = darkest), clamped to the ramp.
    uint8_t operator()(int k) const { return uint8_t(first + std::clamp(k, 0, count - 1)); }
};

RampRef ramp(std::string_view name)
{
    int first = 0;
    for (const PaletteRamp& r : paletteRamps()) {
        if (name == r.name) return {first, r.count};
        first += r.count;
    }
    assert(false && "no such ramp");
    return {0, 1};
}

/// A well-mixed 32-bit hash of integer coordinates (a few xor-shift-multiply rounds): the
/// textures' randomness, the same on every platform.
uint32_t hash(int x, int y, uint32_t seed)
{
    uint32_t h = uint32_t(x) * 0x8da6b343u ^ uint32_t(y) * 0xd8163841u ^ (seed + 1u) * 0xcb1ab31fu;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return h;
}

/// An integer in [−span, span] from the hash.
int jitter(int x, int y, uint32_t seed, int span)
{
    return int(hash(x, y, seed) % uint32_t(2 * span + 1)) - span;
}

constexpr int kN = kTextureSize;

int wrap(int v)
{
    return ((v % kN) + kN) % kN;
}

/// Bricks or stone blocks: courses `height` texels high of blocks `width` wide, every other
/// course shifted by half a block, with a lit top and left edge, a shaded bottom and right
/// edge, and a mortar seam.
uint8_t block(int x, int y, int width, int height, RampRef face, int base, int spread, RampRef seam, int seamShade, uint32_t seed)
{
    const int course = y / height, yy = y % height;
    const int shifted = x + (course % 2) * width / 2;
    const int xx = shifted % width, column = (shifted / width) % (kN / width);
    if (yy == height - 1 || xx == width - 1) return seam(seamShade + jitter(x, y, seed, 1));
    int shade = base + int(hash(column, course, seed) % uint32_t(spread)) + jitter(x, y, seed + 1, 1);
    if (yy == 0 || xx == 0) shade += 3;
    if (yy == height - 2 || xx == width - 2) shade -= 2;
    return face(shade);
}

uint8_t bricks(int x, int y)
{
    return block(x, y, 32, 16, ramp("reds"), 6, 4, ramp("greys"), 9, 11);
}

uint8_t stone(int x, int y)
{
    return block(x, y, 32, 16, ramp("greys"), 12, 5, ramp("greys"), 5, 23);
}

uint8_t wood(int x, int y)
{
    const RampRef browns = ramp("browns");
    const int plank = x / 16, xx = x % 16;
    if (xx == 0) return browns(3);
    int shade = 12 + int(hash(plank, 0, 5) % 5u) + jitter(x, y, 6, 1);
    // Grain: darker streaks running down the plank, wandering by a texel every few rows.
    if ((xx + int(hash(plank, y / 6, 7) % 3u)) % 5 == 0) shade -= 3;
    if (xx == 15) shade -= 2;
    return browns(shade);
}

/// Flagstones: irregular stones around nine jittered points (a Voronoi diagram on the
/// wrapped tile), a gap where a texel is nearly as close to a second stone as to its own.
uint8_t flagstones(int x, int y)
{
    const RampRef tans = ramp("tans"), browns = ramp("browns");
    int nearest = 1 << 30, second = 1 << 30, stone = 0;
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            const int cx = i * 21 + 10 + jitter(i, j, 31, 6), cy = j * 21 + 10 + jitter(i, j, 37, 6);
            // Nearest image of the point on the 64-periodic tile.
            int dx = std::abs(x - cx), dy = std::abs(y - cy);
            dx = std::min(dx, kN - dx);
            dy = std::min(dy, kN - dy);
            const int d = dx * dx + dy * dy;
            if (d < nearest) {
                second = nearest;
                nearest = d;
                stone = j * 3 + i;
            } else if (d < second) {
                second = d;
            }
        }
    }
    // Squared distances: the bisector between two stones is where √second − √nearest = 0.
    if (std::sqrt(double(second)) - std::sqrt(double(nearest)) < 1.6) return browns(4 + jitter(x, y, 41, 1));
    return tans(6 + int(hash(stone, 0, 43) % 4u) + jitter(x, y, 47, 1));
}

/// Ceiling panels: 32-texel squares with dark seams, bevelled edges and a rivet in each corner.
uint8_t ceiling(int x, int y)
{
    const RampRef steel = ramp("steel");
    const int xx = x % 32, yy = y % 32;
    if (xx == 0 || yy == 0) return steel(3);
    const bool rivet = (xx == 4 || xx == 28) && (yy == 4 || yy == 28);
    if (rivet) return steel(21);
    int shade = 13 + jitter(x, y, 53, 1);
    if (xx == 1 || yy == 1) shade += 3;
    if (xx == 31 || yy == 31) shade -= 3;
    return steel(shade);
}

/// Moss: value noise on an 8-texel lattice (wrapped), greens with olive in the low places.
uint8_t moss(int x, int y)
{
    auto lattice = [](int i, int j) { return double(hash(wrap(i * 8) / 8, wrap(j * 8) / 8, 59) % 1000u) / 999.0; };
    const int i = x / 8, j = y / 8;
    const double u = (x % 8) / 8.0, v = (y % 8) / 8.0;
    const double value = (lattice(i, j) * (1 - u) + lattice(i + 1, j) * u) * (1 - v) +
                         (lattice(i, j + 1) * (1 - u) + lattice(i + 1, j + 1) * u) * v;
    const int shade = int(value * 8.0) + jitter(x, y, 61, 1);
    if (value < 0.3) return ramp("olive")(5 + shade);
    return ramp("greens")(4 + shade);
}

Image imageFromIndices(const std::vector<uint8_t>& indices, int width, int height, const std::vector<uint8_t>& alpha,
                       const std::string& name)
{
    const Palette palette = colorTables().palette;
    Image image;
    image.name = name;
    image.width = width;
    image.height = height;
    image.pixels.resize(size_t(width) * size_t(height) * 4);
    for (size_t i = 0; i < indices.size(); ++i) {
        const Rgb& c = palette[indices[i]];
        std::copy(c.begin(), c.end(), image.pixels.begin() + ptrdiff_t(4 * i));
        image.pixels[4 * i + 3] = alpha.empty() ? 255 : alpha[i];
    }
    return image;
}

const char* textureName(LevelTexture texture)
{
    switch (texture) {
    case LevelTexture::Bricks: return "bricks";
    case LevelTexture::Stone: return "stone";
    case LevelTexture::Wood: return "wood";
    case LevelTexture::Flagstones: return "flagstones";
    case LevelTexture::Ceiling: return "ceiling";
    case LevelTexture::Moss: return "moss";
    case LevelTexture::Count: break;
    }
    return "?";
}

} // namespace

std::vector<uint8_t> makeTextureIndices(LevelTexture texture)
{
    uint8_t (*texel)(int, int) = nullptr;
    switch (texture) {
    case LevelTexture::Bricks: texel = bricks; break;
    case LevelTexture::Stone: texel = stone; break;
    case LevelTexture::Wood: texel = wood; break;
    case LevelTexture::Flagstones: texel = flagstones; break;
    case LevelTexture::Ceiling: texel = ceiling; break;
    case LevelTexture::Moss: texel = moss; break;
    case LevelTexture::Count: break;
    }
    assert(texel);
    std::vector<uint8_t> indices(size_t(kN) * kN);
    for (int y = 0; y < kN; ++y)
        for (int x = 0; x < kN; ++x) indices[size_t(y) * kN + size_t(x)] = texel(x, y);
    return indices;
}

Image makeTextureImage(LevelTexture texture)
{
    return imageFromIndices(makeTextureIndices(texture), kN, kN, {}, textureName(texture));
}

Image makeSpriteImage(ThingKind kind)
{
    const RampRef steel = ramp("steel"), greys = ramp("greys"), yellows = ramp("yellows"), oranges = ramp("oranges"),
                  browns = ramp("browns");
    // One texel a map unit, as Doom's sprites: the lamp is 24 × 64 (0.75 m × 2 m), the barrel
    // 24 × 32.
    const int width = 24, height = kind == ThingKind::Lamp ? 64 : 32;
    std::vector<uint8_t> indices(size_t(width) * height, 0), alpha(indices.size(), 0);
    auto set = [&](int x, int y, uint8_t index) {
        indices[size_t(y) * width + size_t(x)] = index;
        alpha[size_t(y) * width + size_t(x)] = 255;
    };
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const double cx = x + 0.5 - width / 2.0;
            if (kind == ThingKind::Lamp) {
                // A glowing globe (white centre, yellow, orange rim) on a pole with a foot.
                const double gy = y + 0.5 - 11.0;
                const double r = std::sqrt(cx * cx / (9.5 * 9.5) + gy * gy / (9.5 * 9.5));
                if (r < 1.0) set(x, y, r < 0.35 ? greys(31) : r < 0.8 ? yellows(7 - int((r - 0.35) * 8.0)) : oranges(12));
                else if (y >= 20 && y < 58 && std::abs(cx) < 2.0) set(x, y, steel(cx < 0.0 ? 14 : 8));
                else if (y >= 58 && std::abs(cx) < 8.0 - (63 - y) * 0.5) set(x, y, steel(y == 58 ? 16 : 10 - int(std::abs(cx)) / 2));
            } else {
                // A wooden barrel: rounded top and bottom, shaded as a cylinder, with two steel hoops.
                const double half = 10.5 - (y < 3 ? 3 - y : y > 28 ? y - 28 : 0) * 1.0;
                if (std::abs(cx) >= half) continue;
                const double facing = std::cos(cx / 11.0 * 1.5); // lit from the front, darker to the sides
                const bool hoop = (y >= 6 && y <= 7) || (y >= 24 && y <= 25);
                const int shade = int(facing * 10.0) + (cx < 0.0 ? 2 : 0);
                if (y < 2) set(x, y, browns(6));
                else set(x, y, hoop ? steel(4 + shade) : browns(6 + shade + ((x + int(hash(x, 0, 71) % 3u)) % 4 == 0 ? -2 : 0)));
            }
        }
    }
    // Transparent texels take an opaque neighbour's colour (two rings of them), so filtering
    // in normal frames does not darken the outline (as render::makeBuiltinSprite's sprites).
    std::vector<bool> coloured(alpha.size());
    for (size_t i = 0; i < alpha.size(); ++i) coloured[i] = alpha[i] != 0;
    for (int ring = 0; ring < 2; ++ring) {
        std::vector<bool> next = coloured;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const size_t i = size_t(y) * width + size_t(x);
                for (int n = 0; n < 9 && !next[i]; ++n) {
                    const int nx = x + n % 3 - 1, ny = y + n / 3 - 1;
                    if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                    const size_t j = size_t(ny) * width + size_t(nx);
                    if (!coloured[j]) continue;
                    indices[i] = indices[j];
                    next[i] = true;
                }
            }
        }
        coloured = std::move(next);
    }
    return imageFromIndices(indices, width, height, alpha, kind == ThingKind::Lamp ? "lamp" : "barrel");
}

std::vector<LevelSector> demoLevelSectors()
{
    std::vector<LevelSector> s(5);
    s[0].sector = {{0, 0}, {256, 256}, 208}; // start room, bright
    s[1].sector = {{256, 96}, {512, 160}, 96}; // corridor
    s[1].ceiling = 96;
    s[1].wallTexture = LevelTexture::Wood;
    s[2].sector = {{512, -64}, {896, 320}, 160}; // hall
    s[2].ceiling = 192;
    s[2].wallTexture = LevelTexture::Bricks;
    s[3].sector = {{896, 192}, {1024, 320}, 24}; // dark side room, off the corridor's axis
    s[3].floorTexture = LevelTexture::Moss;
    s[4].sector = {{640, 320}, {768, 448}, 0}; // nook, lit only by the hall's spill
    s[4].wallTexture = LevelTexture::Bricks;
    s[4].floorTexture = LevelTexture::Moss;
    return s;
}

std::vector<Thing> demoLevelThings()
{
    return {
        {ThingKind::Lamp, {208, 40}},    // start room, to the left of the view
        {ThingKind::Barrel, {200, 180}}, // start room, to the right
        {ThingKind::Lamp, {860, 128}},   // hall, at the far end of the corridor's axis
        {ThingKind::Barrel, {640, 108}}, // hall, seen down the corridor
        {ThingKind::Barrel, {700, 150}},
        {ThingKind::Barrel, {704, 400}}, // nook
        {ThingKind::Barrel, {960, 256}}, // dark side room
    };
}

namespace {

constexpr float kUnit = 1.0f / 32.0f; // metres per map unit

/// A quad with corners a, b, c, d (in order around it), their uvs, facing `facing`.
void addQuad(Scene& scene, std::array<glm::vec3, 4> corners, std::array<glm::vec2, 4> uvs, glm::vec3 facing,
             int material, const std::string& name)
{
    // Counter-clockwise seen from the side `facing` points to (GL's front faces).
    if (glm::dot(glm::cross(corners[1] - corners[0], corners[2] - corners[0]), facing) < 0.0f) {
        std::swap(corners[1], corners[3]);
        std::swap(uvs[1], uvs[3]);
    }
    Primitive p;
    for (size_t i = 0; i < 4; ++i) {
        Vertex v;
        v.position = corners[i];
        v.normal = glm::normalize(facing);
        v.uv0 = uvs[i];
        p.vertices.push_back(v);
        p.bounds.extend(corners[i]);
    }
    p.indices = {0, 1, 2, 0, 2, 3};
    p.material = material;
    Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(std::move(p));
    scene.meshes.push_back(std::move(mesh));
    Node node;
    node.name = name;
    node.mesh = int(scene.meshes.size() - 1);
    scene.addNode(std::move(node));
}

glm::vec3 world(int x, int height, int z)
{
    return glm::vec3(float(x), float(height), float(z)) * kUnit;
}

/// The index of the sector whose rectangle holds (x, z), or -1.
int sectorAt(const std::vector<LevelSector>& level, glm::ivec2 p)
{
    for (size_t i = 0; i < level.size(); ++i) {
        const Sector& s = level[i].sector;
        if (p.x >= s.min.x && p.x < s.max.x && p.y >= s.min.y && p.y < s.max.y) return int(i);
    }
    return -1;
}

} // namespace

Scene makeDemoLevel()
{
    const std::vector<LevelSector> level = demoLevelSectors();
    std::vector<Sector> sectors;
    for (const LevelSector& l : level) sectors.push_back(l.sector);
    const std::vector<int> light = spreadLight(sectors, kDemoLevelAttenuation);

    Scene scene;
    scene.name = "doom";
    // Doom filtered nothing: nearest texels, no mipmaps, repeated.
    Sampler sampler;
    sampler.magFilter = sampler.minFilter = Filter::Nearest;
    sampler.mipmaps = false;
    scene.samplers.push_back(sampler);
    for (int t = 0; t < int(LevelTexture::Count); ++t) scene.images.push_back(makeTextureImage(LevelTexture(t)));

    // One material per sector and texture (the sector's light is the material's).
    auto material = [&](size_t sector, LevelTexture texture, const char* part) {
        Material m;
        m.name = "sector " + std::to_string(sector) + " " + part;
        m.baseColorFactor = glm::vec4(1.0f);
        m.baseColorTexture.image = int(texture);
        m.baseColorTexture.sampler = 0;
        m.metallicFactor = 0.0f;
        m.roughnessFactor = 0.9f;
        // For the classic models: a dull highlight, not the near-diffuse lobe of roughness 0.9.
        m.shininess = 10.0f;
        m.shading.model = ShadingModel::Doom;
        m.sectorLight = light[sector];
        scene.materials.push_back(m);
        return int(scene.materials.size() - 1);
    };
    constexpr float kTexture = float(kTextureSize); // map units a texture repeat
    for (size_t i = 0; i < level.size(); ++i) {
        const LevelSector& l = level[i];
        const glm::ivec2 lo = l.sector.min, hi = l.sector.max;
        const std::string name = "sector " + std::to_string(i);
        // Flats are aligned to the world grid, as Doom's: uv = (x, z) / 64.
        auto flatUv = [&](int x, int z) { return glm::vec2(float(x), float(z)) / kTexture; };
        addQuad(scene, {world(lo.x, l.floor, lo.y), world(lo.x, l.floor, hi.y), world(hi.x, l.floor, hi.y), world(hi.x, l.floor, lo.y)},
                {flatUv(lo.x, lo.y), flatUv(lo.x, hi.y), flatUv(hi.x, hi.y), flatUv(hi.x, lo.y)}, {0, 1, 0},
                material(i, l.floorTexture, "floor"), name + " floor");
        addQuad(scene,
                {world(lo.x, l.ceiling, lo.y), world(lo.x, l.ceiling, hi.y), world(hi.x, l.ceiling, hi.y), world(hi.x, l.ceiling, lo.y)},
                {flatUv(lo.x, lo.y), flatUv(lo.x, hi.y), flatUv(hi.x, hi.y), flatUv(hi.x, lo.y)}, {0, -1, 0},
                material(i, l.ceilingTexture, "ceiling"), name + " ceiling");
        const int wall = material(i, l.wallTexture, "wall");
        // The four edges: fixed coordinate, span, and the inward normal (x, z).
        struct Edge {
            bool alongX; // the edge runs along x (fixed z)
            int fixed, from, to;
            glm::vec3 inward;
        };
        const Edge edges[4] = {{true, lo.y, lo.x, hi.x, {0, 0, 1}}, {true, hi.y, lo.x, hi.x, {0, 0, -1}},
                               {false, lo.x, lo.y, hi.y, {1, 0, 0}}, {false, hi.x, lo.y, hi.y, {-1, 0, 0}}};
        for (const Edge& e : edges) {
            // Openings: where another sector touches this edge; above a lower neighbour
            // ceiling the opening is walled up to this sector's ceiling.
            struct Opening {
                int from, to, ceiling;
            };
            std::vector<Opening> openings;
            for (size_t j = 0; j < level.size(); ++j) {
                if (j == i) continue;
                const Sector& t = level[j].sector;
                const bool touches = e.alongX ? (t.min.y == e.fixed || t.max.y == e.fixed) : (t.min.x == e.fixed || t.max.x == e.fixed);
                if (!touches) continue;
                const int a = std::max(e.from, e.alongX ? t.min.x : t.min.y), b = std::min(e.to, e.alongX ? t.max.x : t.max.y);
                if (b > a) openings.push_back({a, b, level[j].ceiling});
            }
            std::sort(openings.begin(), openings.end(), [](const Opening& p, const Opening& q) { return p.from < q.from; });
            auto point = [&](int along, int height) { return e.alongX ? world(along, height, e.fixed) : world(e.fixed, height, along); };
            // Wall textures run along the wall (u) and down from the sector's ceiling (v), as
            // Doom's upper-pegged walls.
            auto uv = [&](int along, int height) { return glm::vec2(float(along), float(l.ceiling - height)) / kTexture; };
            auto addWall = [&](int a, int b, int bottom, int top) {
                if (b <= a || top <= bottom) return;
                addQuad(scene, {point(a, bottom), point(b, bottom), point(b, top), point(a, top)},
                        {uv(a, bottom), uv(b, bottom), uv(b, top), uv(a, top)}, e.inward, wall, name + " wall");
            };
            int cursor = e.from;
            for (const Opening& o : openings) {
                addWall(cursor, o.from, l.floor, l.ceiling);
                addWall(o.from, o.to, std::min(o.ceiling, l.ceiling), l.ceiling);
                cursor = std::max(cursor, o.to);
            }
            addWall(cursor, e.to, l.floor, l.ceiling);
        }
    }

    // Things: one billboard group per kind and sector (a group has one sector light), turning
    // about the vertical as Doom's sprites did, cutout, standing on the floor.
    const Image lamp = makeSpriteImage(ThingKind::Lamp), barrel = makeSpriteImage(ThingKind::Barrel);
    scene.images.push_back(lamp);
    const int lampImage = int(scene.images.size() - 1);
    scene.images.push_back(barrel);
    const int barrelImage = int(scene.images.size() - 1);
    for (const Thing& thing : demoLevelThings()) {
        const int sector = sectorAt(level, thing.position);
        assert(sector >= 0);
        const bool isLamp = thing.kind == ThingKind::Lamp;
        // Lamps are full bright (as Doom's lamp frames), barrels take their sector's light.
        const int sectorLight = isLamp ? 255 : light[size_t(sector)];
        const std::string name = std::string(isLamp ? "lamps" : "barrels") + " in sector " + std::to_string(sector);
        auto group = std::find_if(scene.billboards.begin(), scene.billboards.end(),
                                  [&](const BillboardGroup& g) { return g.name == name; });
        if (group == scene.billboards.end()) {
            BillboardGroup g;
            g.name = name;
            g.kind = BillboardKind::AxisAligned;
            const Image& image = isLamp ? lamp : barrel;
            g.size = glm::vec2(float(image.width), float(image.height)) * kUnit;
            g.anchor = {0.5f, 0.0f};
            g.alphaMode = AlphaMode::Mask;
            g.image = isLamp ? lampImage : barrelImage;
            g.sectorLight = sectorLight;
            scene.billboards.push_back(g);
            group = scene.billboards.end() - 1;
        }
        Billboard b;
        b.position = world(thing.position.x, level[size_t(sector)].floor, thing.position.y);
        group->billboards.push_back(b);
        if (isLamp) {
            // A warm point light in the globe, for the models that use lights.
            Light l;
            l.name = "lamp";
            l.type = Light::Type::Point;
            l.color = {1.0f, 0.85f, 0.6f};
            l.intensity = 25.0f; // cd
            addLight(scene, l, world(thing.position.x, level[size_t(sector)].floor + 53, thing.position.y), {0, -1, 0});
        }
    }

    // The camera: in the start room, eye height 41 units (Doom's viewheight), looking down the
    // corridor (+x; a camera looks down its local -Z).
    Camera camera;
    camera.name = "doom";
    camera.yfov = glm::radians(60.0f);
    scene.cameras.push_back(camera);
    Node node;
    node.name = "doom camera";
    node.translation = world(64, 41, 128);
    node.rotation = glm::angleAxis(glm::radians(-80.0f), glm::vec3(0, 1, 0));
    node.camera = int(scene.cameras.size() - 1);
    scene.addNode(node);
    return scene;
}

} // namespace specula::scene::doom
