#pragma once
// The forward renderer: a scene in, an HDR frame and a tone-mapped image out.
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "core/ImageIO.h"
#include "render/Tonemap.h"
#include "render/View.h"
#include "scene/Scene.h"

namespace specula::gl {
class State;
}

namespace specula::render {

class LightBuffer;

enum class BrdfGeometry { SmithGGX, SchlickGGX };
std::optional<BrdfGeometry> parseBrdfGeometry(std::string_view name);

/// What a frame looks like. Zero values are not all defaults; use the initialisers.
struct FrameSettings {
    int width = 1280;
    int height = 720;
    int msaa = 4;                          ///< 1 = one sample at each pixel centre
    float exposureEv = 0.0f;               ///< image multiplied by 2^exposureEv
    Tonemap tonemap = Tonemap::Neutral;
    float reinhardWhite = 4.0f;            ///< white point of reinhard-ext (cd/m² after exposure)
    BrdfGeometry brdfGeometry = BrdfGeometry::SmithGGX;
    glm::vec3 background{0.0f};            ///< radiance behind the scene, cd/m²
    glm::vec3 ambient{0.0f};               ///< constant ambient radiance for the diffuse lobe
};

/// GPU milliseconds per pass of the last frame (timer queries), when timing is on.
struct PassTiming {
    const char* name;
    double gpuMs;
};

struct FrameStats {
    int drawCalls = 0;
    size_t triangles = 0;    ///< submitted after culling
    std::vector<PassTiming> passes;
};

class Renderer {
public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Uploads a scene (meshes, textures, materials) and its lights.
    void setScene(const scene::Scene& scene);
    LightBuffer& lights();

    /// Renders one frame into the renderer's targets.
    void render(const View& view, const FrameSettings& settings);

    /// The last frame, tone-mapped and sRGB-encoded, top row first.
    ImageRGBA8 readImage() const;
    /// The last frame's linear radiance × 2^exposureEv (before tone mapping), top row first.
    ImageFloat readRadiance() const;

    /// Measure each pass with GPU timer queries (waits for the GPU at the end of a frame).
    void setGpuTiming(bool enabled);
    const FrameStats& stats() const;
    gl::State& state();

    /// Compiles the programs `settings` needs now rather than on first use.
    void prepare(const FrameSettings& settings);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace specula::render
