#include "scene/DoomLighting.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "scene/Procedural.h"

namespace specula::scene::doom {

std::vector<std::pair<int, int>> adjacentSectors(const std::vector<Sector>& sectors)
{
    std::vector<std::pair<int, int>> pairs;
    for (size_t a = 0; a < sectors.size(); ++a) {
        for (size_t b = a + 1; b < sectors.size(); ++b) {
            const Sector& s = sectors[a];
            const Sector& t = sectors[b];
            // Overlap of the two rectangles' extents along each axis.
            const int overlapX = std::min(s.max.x, t.max.x) - std::max(s.min.x, t.min.x);
            const int overlapZ = std::min(s.max.y, t.max.y) - std::max(s.min.y, t.min.y);
            // Touching along an edge: zero extent on one axis, positive on the other.
            if ((overlapX == 0 && overlapZ > 0) || (overlapZ == 0 && overlapX > 0)) pairs.emplace_back(int(a), int(b));
        }
    }
    return pairs;
}

std::vector<int> spreadLight(const std::vector<Sector>& sectors, int attenuation)
{
    std::vector<int> level(sectors.size());
    for (size_t i = 0; i < sectors.size(); ++i) level[i] = std::clamp(sectors[i].light, 0, 255);
    const auto pairs = adjacentSectors(sectors);
    // Bellman-Ford style relaxation: levels only rise, at most 255 times, so it terminates.
    for (bool changed = true; changed;) {
        changed = false;
        for (const auto& [a, b] : pairs) {
            for (auto [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
                const int spread = level[size_t(from)] - attenuation;
                if (spread > level[size_t(to)]) {
                    level[size_t(to)] = spread;
                    changed = true;
                }
            }
        }
    }
    return level;
}

int colormapIndex(int light, double distance)
{
    constexpr int kLightLevels = 16; // LIGHTLEVELS: light >> LIGHTSEGSHIFT (4)
    const int lightNumber = std::clamp(light, 0, 255) >> 4;
    const int startmap = ((kLightLevels - 1 - lightNumber) * 2) * kColormaps / kLightLevels;
    // Distance in units of 16 map units (LIGHTZSHIFT), MAXLIGHTZ = 128 steps.
    const int z = std::clamp(int(std::max(distance, 0.0) / 16.0), 0, 127);
    const int scale = 160 / (z + 1); // (SCREENWIDTH / 2) / (z + 1)
    const int level = startmap - scale / 2; // DISTMAP = 2
    return std::clamp(level, 0, kColormaps - 1);
}

std::array<Rgb, 256> makePalette()
{
    std::array<Rgb, 256> palette{};
    size_t i = 0;
    for (int r = 0; r < 6; ++r)
        for (int g = 0; g < 6; ++g)
            for (int b = 0; b < 6; ++b) palette[i++] = {uint8_t(r * 51), uint8_t(g * 51), uint8_t(b * 51)};
    // Greys between the cube's six, for smooth dark ramps (the colour map needs them most).
    for (int k = 0; k < 40; ++k) {
        const uint8_t v = uint8_t(std::lround((k + 1) * 255.0 / 41.0));
        palette[i++] = {v, v, v};
    }
    return palette;
}

uint8_t nearestIndex(const std::array<Rgb, 256>& palette, Rgb c)
{
    int best = 0, bestDistance = 1 << 30;
    for (int i = 0; i < 256; ++i) {
        const int dr = int(palette[size_t(i)][0]) - c[0], dg = int(palette[size_t(i)][1]) - c[1], db = int(palette[size_t(i)][2]) - c[2];
        const int d = dr * dr + dg * dg + db * db;
        if (d < bestDistance) bestDistance = d, best = i;
    }
    return uint8_t(best);
}

std::vector<std::array<uint8_t, 256>> makeColormap(const std::array<Rgb, 256>& palette)
{
    std::vector<std::array<uint8_t, 256>> map(kColormaps);
    for (int level = 0; level < kColormaps; ++level) {
        const double scale = 1.0 - double(level) / kColormaps;
        for (int i = 0; i < 256; ++i) {
            Rgb c;
            for (int ch = 0; ch < 3; ++ch) c[size_t(ch)] = uint8_t(std::lround(palette[size_t(i)][size_t(ch)] * scale));
            map[size_t(level)][size_t(i)] = nearestIndex(palette, c);
        }
    }
    return map;
}

std::vector<LevelSector> demoLevelSectors()
{
    std::vector<LevelSector> s(5);
    s[0].sector = {{0, 0}, {256, 256}, 208};      // start room, bright
    s[1].sector = {{256, 96}, {512, 160}, 96};    // corridor
    s[1].ceiling = 96;
    s[1].wallColor = {0.30f, 0.20f, 0.10f};
    s[2].sector = {{512, -64}, {896, 320}, 160};  // hall
    s[2].ceiling = 192;
    s[2].wallColor = {0.40f, 0.12f, 0.06f};
    s[3].sector = {{896, 192}, {1024, 320}, 24};  // dark side room, off the corridor's axis
    s[3].wallColor = {0.10f, 0.10f, 0.30f};
    s[4].sector = {{640, 320}, {768, 448}, 0};    // nook, lit only by the hall's spill
    s[4].floorColor = {0.15f, 0.30f, 0.08f};
    return s;
}

namespace {

constexpr float kUnit = 1.0f / 32.0f; // metres per map unit

void addQuad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 facing, const Material& material,
             const std::string& name)
{
    // Counter-clockwise seen from the side `facing` points to (GL's front faces).
    if (glm::dot(glm::cross(b - a, c - a), facing) < 0.0f) std::swap(b, d);
    Primitive p;
    const glm::vec3 corners[4] = {a, b, c, d};
    const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; ++i) {
        Vertex v;
        v.position = corners[i];
        v.normal = glm::normalize(facing);
        v.uv0 = uvs[i];
        p.vertices.push_back(v);
        p.bounds.extend(corners[i]);
    }
    p.indices = {0, 1, 2, 0, 2, 3};
    addShape(scene, std::move(p), material, glm::mat4(1.0f), name);
}

glm::vec3 world(int x, int height, int z)
{
    return glm::vec3(float(x), float(height), float(z)) * kUnit;
}

} // namespace

Scene makeDemoLevel()
{
    const std::vector<LevelSector> level = demoLevelSectors();
    std::vector<Sector> sectors;
    for (const LevelSector& l : level) sectors.push_back(l.sector);
    const std::vector<int> light = spreadLight(sectors, 64);

    Scene scene;
    scene.name = "doom";
    for (size_t i = 0; i < level.size(); ++i) {
        const LevelSector& l = level[i];
        const glm::ivec2 lo = l.sector.min, hi = l.sector.max;
        auto material = [&](glm::vec3 color, const char* part) {
            Material m;
            m.name = "sector " + std::to_string(i) + " " + part;
            m.baseColorFactor = glm::vec4(color, 1.0f);
            m.metallicFactor = 0.0f;
            m.roughnessFactor = 0.9f;
            m.shading.model = ShadingModel::Doom;
            m.sectorLight = light[i];
            return m;
        };
        const std::string name = "sector " + std::to_string(i);
        addQuad(scene, world(lo.x, l.floor, lo.y), world(lo.x, l.floor, hi.y), world(hi.x, l.floor, hi.y),
                world(hi.x, l.floor, lo.y), {0, 1, 0}, material(l.floorColor, "floor"), name + " floor");
        addQuad(scene, world(lo.x, l.ceiling, lo.y), world(lo.x, l.ceiling, hi.y), world(hi.x, l.ceiling, hi.y),
                world(hi.x, l.ceiling, lo.y), {0, -1, 0}, material(l.ceilingColor, "ceiling"), name + " ceiling");
        const Material wall = material(l.wallColor, "wall");
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
            auto addWall = [&](int a, int b, int bottom, int top) {
                if (b <= a || top <= bottom) return;
                addQuad(scene, point(a, bottom), point(b, bottom), point(b, top), point(a, top), e.inward, wall, name + " wall");
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
