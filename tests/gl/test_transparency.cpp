// Transparent surfaces (docs/transparency.md) against expectations worked out here, not by
// the renderer: the BRDF's lobes on the CPU (shading/Brdf.h) for the blend modes, exact
// Fresnel at normal incidence and Beer–Lambert for transmission, McGuire & Bavoil's weighted
// mean for order-independent transparency, Porter–Duff "over" for sorted blending.
#include "GlTestContext.h"
#include "RadianceFrame.h"
#include "ImageProbe.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render/DrawList.h"
#include "render/GpuScene.h"
#include "render/Renderer.h"
#include "scene/DemoScenes.h"
#include "scene/GltfImporter.h"
#include "scene/Procedural.h"
#include "shading/Brdf.h"

using namespace specula;
using specula::test::GlTest;
using glm::dvec3;
using specula::test::pixelRay;
using specula::test::Ray;

namespace {

constexpr int kSize = 96;

ImageFloat renderScene(const scene::Scene& s, const render::View& view, const render::FrameSettings& settings)
{
    render::Renderer renderer;
    renderer.setScene(s);
    renderer.render(view, settings);
    return renderer.readRadiance();
}

dvec3 pixel(const ImageFloat& image, int x, int y)
{
    const float* p = &image.pixels[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
    return dvec3(p[0], p[1], p[2]);
}

/// Where the ray meets the square of half side `half` (world units) centred at the origin of
/// `frame`, a makePlane quad (in its local XZ plane, facing local +Y), or nothing.
std::optional<dvec3> hitQuad(const Ray& ray, const glm::dmat4& frame, double half)
{
    const dvec3 center(frame[3]), right = glm::normalize(dvec3(frame[0])), up = glm::normalize(dvec3(frame[2])),
                normal = glm::normalize(dvec3(frame[1]));
    const double denominator = glm::dot(ray.direction, normal);
    if (std::abs(denominator) < 1e-9) return std::nullopt;
    const double t = glm::dot(center - ray.origin, normal) / denominator;
    const dvec3 p = ray.origin + t * ray.direction;
    if (t <= 0.0 || std::abs(glm::dot(p - center, right)) > half || std::abs(glm::dot(p - center, up)) > half) return std::nullopt;
    return p;
}

/// A quad of half side `half` facing +Z under `transform` (makePlane faces +Y).
glm::mat4 facingZ(const glm::mat4& transform)
{
    return transform * glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0));
}

/// An emissive backdrop: a quad of side 8 at z = -2 facing the camera, radiance `radiance`,
/// times a checker texture when `checker` (so that a shifted image could not pass).
void addBackdrop(scene::Scene& s, glm::vec3 radiance, bool checker, float z = -2.0f)
{
    scene::Material m;
    m.name = "backdrop";
    m.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f); // no diffuse: it shows its emission only
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 1.0f;
    m.emissiveFactor = radiance;
    if (checker) {
        scene::Image image;
        image.name = "checker";
        image.width = image.height = 16;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                const bool odd = ((x + y) & 1) != 0;
                const uint8_t texel[4] = {uint8_t(odd ? 255 : 40), uint8_t(odd ? 90 : 200), uint8_t(odd ? 20 : 255), 255};
                image.pixels.insert(image.pixels.end(), texel, texel + 4);
            }
        s.images.push_back(std::move(image));
        scene::Sampler nearest;
        nearest.magFilter = nearest.minFilter = scene::Filter::Nearest;
        nearest.mipmaps = false;
        s.samplers.push_back(nearest);
        m.emissiveTexture.image = int(s.images.size() - 1);
        m.emissiveTexture.sampler = int(s.samplers.size() - 1);
    }
    scene::addShape(s, scene::makePlane(8.0f), m, facingZ(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, z))), "backdrop");
}

render::View frontView(float distance = 4.0f)
{
    return render::lookAtView({0.0f, 0.0f, distance}, {0, 0, 0}, {0, 1, 0}, glm::radians(30.0f), 1.0f, 0.1f, 20.0f);
}

// -- blend modes -----------------------------------------------------------------------------

struct BlendCase {
    const char* name;
    scene::AlphaMode alphaMode;
    scene::BlendMode blendMode;
    std::optional<scene::BlendMode> frameOverride;
    double diffuseScale, specularScale; ///< what the blend mode must leave of each lobe
};

// Tolerance as in test_shading.cpp: 1.5% relative plus 2e-3 cd/m² absolute (half floats,
// single precision, a faceted sphere's interpolated normals).
constexpr double kRelative = 0.015;
constexpr double kAbsolute = 2e-3;

/// A sphere lit by one point light over a black background, each pixel against the CPU's
/// lobes: diffuseScale × diffuse + specularScale × specular. Returns the peak pixel's
/// specular (CPU) and the GPU's value there.
struct Peak {
    double cpuSpecular = 0.0, cpuDiffuse = 0.0, gpu = 0.0;
};
Peak renderBlendCase(const BlendCase& c, float alpha)
{
    scene::Scene s;
    scene::Material material;
    material.baseColorFactor = glm::vec4(0.8f, 0.3f, 0.2f, c.alphaMode == scene::AlphaMode::Blend ? alpha : 1.0f);
    material.metallicFactor = 0.0f;
    material.roughnessFactor = 0.3f;
    material.alphaMode = c.alphaMode;
    material.blendMode = c.blendMode;
    scene::addShape(s, scene::makeUvSphere(1.0f, 256, 128), material, glm::mat4(1.0f), "sphere");
    scene::Light light;
    light.type = scene::Light::Type::Point;
    light.intensity = 30.0f;
    light.range = 8.0f;
    const glm::vec3 lightPosition(2.0f, 2.5f, 3.0f);
    scene::addLight(s, light, lightPosition, -lightPosition);
    render::FrameSettings settings = test::radianceFrame(kSize, kSize, test::Brdf::Exact);
    settings.blendModeOverride = c.frameOverride;
    const render::View view = frontView();
    const ImageFloat image = renderScene(s, view, settings);

    render::brdf::Surface surface;
    surface.baseColor = dvec3(0.8, 0.3, 0.2);
    surface.metallic = 0.0;
    surface.perceptualRoughness = 0.3;
    Peak peak;
    int tested = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Ray ray = pixelRay(view, x, y, image.width, image.height);
            const double b = glm::dot(ray.origin, ray.direction);
            const double disc = b * b - (glm::dot(ray.origin, ray.origin) - 1.0);
            if (disc <= 0.0) continue;
            const dvec3 p = ray.origin + ray.direction * (-b - std::sqrt(disc));
            const dvec3 n = glm::normalize(p), v = -ray.direction;
            if (glm::dot(n, v) < 0.25) continue; // silhouettes straddle facets and background
            const dvec3 toLight = dvec3(lightPosition) - p;
            const double distance = glm::length(toLight);
            const dvec3 l = toLight / distance;
            const double NoL = glm::dot(n, l);
            dvec3 diffuse(0.0), specular(0.0);
            if (NoL > 0.0) {
                render::brdf::evaluateLobes(surface, n, v, l, diffuse, specular);
                const double e = light.intensity * render::brdf::rangeAttenuation(light.range, distance) * NoL;
                diffuse *= e;
                specular *= e;
            }
            // Premultiplied over black: the pixel is the blended surface's contribution.
            const dvec3 want = diffuse * c.diffuseScale + specular * c.specularScale;
            const dvec3 got = pixel(image, x, y);
            ++tested;
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_LE(std::abs(got[ch] - want[ch]), kRelative * want[ch] + kAbsolute)
                    << c.name << " pixel (" << x << ", " << y << ") channel " << ch << ": GPU " << got[ch] << " CPU " << want[ch];
            if (specular.g > peak.cpuSpecular) peak = {specular.g, diffuse.g, got.g};
        }
    EXPECT_GT(tested, 2000) << c.name;
    return peak;
}

} // namespace

// A clear sphere (alpha 0.1) over black: "transparent" keeps the specular peak of the opaque
// sphere and scales only its diffuse light by alpha; "fade" (glTF's coverage) scales both.
// The frame's override turns a fade material into a transparent one (the gallery's tiles).
TEST_F(GlTest, TransparencyBlendModesKeepOrFadeTheHighlight)
{
    const float alpha = 0.1f;
    using scene::AlphaMode, scene::BlendMode;
    const Peak opaque = renderBlendCase({"opaque", AlphaMode::Opaque, BlendMode::Fade, std::nullopt, 1.0, 1.0}, alpha);
    const Peak transparent = renderBlendCase({"transparent", AlphaMode::Blend, BlendMode::Transparent, std::nullopt, alpha, 1.0}, alpha);
    const Peak fade = renderBlendCase({"fade", AlphaMode::Blend, BlendMode::Fade, std::nullopt, alpha, alpha}, alpha);
    const Peak overridden =
        renderBlendCase({"fade material, transparent frame", AlphaMode::Blend, BlendMode::Fade, BlendMode::Transparent, alpha, 1.0}, alpha);
    // The peak is a highlight: its specular outshines its diffuse, so the checks below mean something.
    ASSERT_GT(opaque.cpuSpecular, 3.0 * opaque.cpuDiffuse);
    // What is left at the peak without the (CPU) diffuse part, scaled as each mode scales it:
    // the opaque sphere's specular peak, whole for transparent, a tenth for fade.
    const double opaqueSpecular = opaque.gpu - opaque.cpuDiffuse;
    EXPECT_NEAR(opaqueSpecular, opaque.cpuSpecular, kRelative * opaque.cpuSpecular);
    EXPECT_NEAR(transparent.gpu - alpha * transparent.cpuDiffuse, opaqueSpecular, kRelative * opaque.cpuSpecular)
        << "the highlight is kept in full";
    EXPECT_NEAR(overridden.gpu - alpha * overridden.cpuDiffuse, opaqueSpecular, kRelative * opaque.cpuSpecular);
    EXPECT_NEAR(fade.gpu - alpha * fade.cpuDiffuse, alpha * opaqueSpecular, kRelative * opaque.cpuSpecular)
        << "fade scales the highlight by alpha";
}

namespace {

// Transmission tolerance: 1% relative plus 2e-3 absolute. Half floats round to 0.05%, the
// opaque frame's copy and its sample add two more roundings, the refracted sample lands on
// the texel centre to within 1e-4 of a texel; a wrong Fresnel factor (0.04) or a shift of
// one texel of the checker (a full colour change) is far outside.
constexpr double kTransmissionRelative = 0.01;

double exactF0(double ior)
{
    return std::pow((ior - 1.0) / (ior + 1.0), 2.0);
}

scene::Material glass(float transmission, float ior, float thickness)
{
    scene::Material m;
    m.name = "glass";
    m.baseColorFactor = glm::vec4(1.0f);
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.0f;
    m.transmissionFactor = transmission;
    m.ior = ior;
    m.thickness = thickness;
    return m;
}

} // namespace

// A thin slab (no volume) of IOR 1.5 and transmission 0.8 over a checker: every pixel behind
// it is the checker's own pixel (nothing shifts) × T (1 − F0), F0 = ((n − 1)/(n + 1))² = 0.04
// (the view is within 8° of normal incidence, where Schlick's F differs from F0 by < 1e-8).
// With one sample and with four (the copy resolves them).
TEST_F(GlTest, TransparencyThinSlabTransmitsWithoutShift)
{
    for (int msaa : {1, 4}) {
        scene::Scene reference;
        addBackdrop(reference, glm::vec3(1.0f), true);
        scene::Scene withSlab = reference;
        const float T = 0.8f, ior = 1.5f;
        const glm::mat4 slab = facingZ(glm::mat4(1.0f));
        scene::addShape(withSlab, scene::makePlane(1.6f), glass(T, ior, 0.0f), slab, "slab");
        render::FrameSettings settings = test::radianceFrame(kSize, kSize, test::Brdf::Exact);
        settings.msaa = msaa;
        const render::View view = frontView();
        const ImageFloat behind = renderScene(reference, view, settings);
        const ImageFloat through = renderScene(withSlab, view, settings);
        const double factor = T * (1.0 - exactF0(ior));
        int tested = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                // Pixels wholly inside the slab (0.78 of its 0.8 half side: clear of its edge's samples).
                if (!hitQuad(pixelRay(view, x, y, kSize, kSize), glm::dmat4(slab), 0.78)) continue;
                ++tested;
                const dvec3 want = factor * pixel(behind, x, y), got = pixel(through, x, y);
                for (int ch = 0; ch < 3; ++ch)
                    ASSERT_LE(std::abs(got[ch] - want[ch]), kTransmissionRelative * want[ch] + kAbsolute)
                        << "msaa " << msaa << " pixel (" << x << ", " << y << ") channel " << ch << ": " << got[ch]
                        << ", expected " << want[ch] << " = " << factor << " x the checker behind";
            }
        EXPECT_GT(tested, 1000);
    }
}

// A volume (KHR_materials_volume) of thickness t, attenuation distance d and colour c over a
// uniform backdrop L transmits (1 − F0) c^(t/d) L (Beer–Lambert); scaled by 2, the object's
// thickness doubles too: c^(2t/d).
TEST_F(GlTest, TransparencyVolumeAttenuatesByBeerLambert)
{
    const double t = 0.5, d = 0.25;
    const dvec3 c(0.9, 0.5, 0.2), L(4.0);
    for (float scale : {1.0f, 2.0f}) {
        scene::Scene s;
        addBackdrop(s, glm::vec3(L), false);
        scene::Material m = glass(1.0f, 1.5f, float(t));
        m.attenuationDistance = float(d);
        m.attenuationColor = glm::vec3(c);
        const glm::mat4 slab = facingZ(glm::scale(glm::mat4(1.0f), glm::vec3(scale)));
        scene::addShape(s, scene::makePlane(0.8f), m, slab, "volume");
        const render::View view = frontView();
        const ImageFloat image = renderScene(s, view, test::radianceFrame(kSize, kSize, test::Brdf::Exact));
        const dvec3 want = (1.0 - exactF0(1.5)) * glm::pow(c, dvec3(scale * t / d)) * L;
        int tested = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                if (!hitQuad(pixelRay(view, x, y, kSize, kSize), glm::dmat4(slab), 0.38 * scale)) continue;
                ++tested;
                const dvec3 got = pixel(image, x, y);
                for (int ch = 0; ch < 3; ++ch)
                    ASSERT_LE(std::abs(got[ch] - want[ch]), kTransmissionRelative * want[ch] + kAbsolute)
                        << "scale " << scale << " pixel (" << x << ", " << y << ") channel " << ch << ": " << got[ch]
                        << ", expected (1 - F0) c^(t/d) L = " << want[ch];
            }
        EXPECT_GT(tested, 300);
    }
}

namespace {

/// transmission_quad.gltf seen from frontView(): where pixel (x, y) meets the quad, clear of its
/// edges and the texel seam, and which texel (0 left, 1 right) it shows; and what it transmits
/// of a uniform backdrop L there, T (1 − F(n·v)) c^(t/d) L (Schlick, F0 0.04), with each texel's
/// factor T and thickness t.
struct QuadVolume {
    double transmission[2], thickness[2];
    dvec3 c;
    double d;
};
std::optional<std::pair<dvec3, int>> quadTexel(const render::View& view, int x, int y)
{
    const auto hit = hitQuad(pixelRay(view, x, y, kSize, kSize), glm::dmat4(facingZ(glm::mat4(1.0f))), 0.97);
    if (!hit || std::abs(hit->x) < 0.03) return std::nullopt;
    return std::pair(*hit, hit->x < 0.0 ? 0 : 1);
}
dvec3 transmittedThroughQuad(const dvec3& hit, int texel, const QuadVolume& v, const dvec3& L)
{
    const double NoV = glm::normalize(dvec3(0.0, 0.0, 4.0) - hit).z;
    const double F = 0.04 + 0.96 * std::pow(1.0 - NoV, 5.0);
    return v.transmission[texel] * (1.0 - F) * glm::pow(v.c, dvec3(v.thickness[texel] / v.d)) * L;
}

} // namespace

// tests/assets/gltf/transmission_quad.gltf (make_transmission.py): the transmission factor 0.9 x
// transmissionTexture's R (128 on the left half, 255 on the right) and the volume's thickness
// 0.5 x thicknessTexture's G (255 left, 64 right, through texCoord 1 and KHR_texture_transform),
// attenuation colour c after d = 0.25 m, over a uniform backdrop L with no light: each pixel is
// T (1 − F(n·v)) c^(t/d) L (Schlick, F0 0.04; the refracted ray still meets the backdrop).
// Broken on purpose (2026-12-07), each failed: the TRANSMISSION_TEXTURES variant reading neither
// texture; the thickness read from R; the uv sets of textures 16 on (the thickness texture's)
// read from the first word of uv sets (GpuMaterial::flags.y, not .z); every uv set taken as 0.
TEST_F(GlTest, TransparencyTransmissionAndThicknessTexturesFromGltf)
{
    scene::Scene s = scene::loadGltf(std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/transmission_quad.gltf");
    ASSERT_EQ(s.materials.size(), 1u);
    const dvec3 L(3.0), c(0.9, 0.5, 0.2);
    const double d = 0.25;
    addBackdrop(s, glm::vec3(L), false);
    const render::View view = frontView();
    const ImageFloat image = renderScene(s, view, test::radianceFrame(kSize, kSize, test::Brdf::Exact));
    const QuadVolume volume{{0.9 * 128.0 / 255.0, 0.9}, {0.5, 0.5 * 64.0 / 255.0}, c, d};
    int tested = 0;
    double textureMatters = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const auto texelHit = quadTexel(view, x, y);
            if (!texelHit) continue;
            const auto& [hit, texel] = *texelHit;
            const dvec3 want = transmittedThroughQuad(hit, texel, volume, L);
            const dvec3 swapped = transmittedThroughQuad(hit, 1 - texel, volume, L), got = pixel(image, x, y);
            ++tested;
            for (int ch = 0; ch < 3; ++ch) {
                const double tolerance = kTransmissionRelative * want[ch] + kAbsolute;
                ASSERT_LE(std::abs(got[ch] - want[ch]), tolerance)
                    << "pixel (" << x << ", " << y << ") channel " << ch << ": " << got[ch] << ", expected T (1 - F) c^(t/d) L = " << want[ch];
                textureMatters = std::max(textureMatters, std::abs(swapped[ch] - want[ch]) / tolerance);
            }
        }
    EXPECT_GT(tested, 1000);
    EXPECT_GT(textureMatters, 3.0); // the other half's texels would be far outside
}

// KHR_animation_pointer on the transmission and the volume of transmission_quad.gltf (the test
// above): its factor LINEAR 0 -> 0.9, its thickness LINEAR 0.5 -> 0.25, the attenuation distance
// STEP 0.25 -> 0.5 at 0.5 s, the attenuation colour LINEAR (0.9, 0.5, 0.2) -> (0.5, 0.9, 0.9), each
// over 1 s: each pixel T (1 - F) c^(t/d) L with the posed values times the textures, and at 0 s
// (factor 0) the quad is opaque: black, with no light, in front of the backdrop. The shadow rule
// and the draw lists follow the factor (with its transmission texture the quad casts, cut out
// texel by texel from a factor of 0.5 up: transmissionCutout). The rest pose gives the
// file's values back. Broken on purpose (2026-12-07), channels off at 0.25 s / 0.75 s: the factor
// not written into the record 21,672 / 21,672 (every channel of the quad); the thickness not
// written 21,672 / 21,672; the distance not written 0 / 21,672 (its step comes at 0.5 s); the
// colour not written 21,672 / 21,672; the TRANSMISSION variant kept at factor 0 and the shadow
// rule's factor not updated each fail the lists' checks (the pixels are the same: T = 0 is black).
TEST_F(GlTest, TransparencyAnimatedTransmissionAndVolume)
{
    scene::Scene s = scene::loadGltf(std::string(SPECULA_SOURCE_DIR) + "/tests/assets/gltf/transmission_quad.gltf");
    ASSERT_EQ(s.materials.size(), 1u);
    scene::Animation animation;
    const auto channel = [&](scene::AnimatedField field, scene::Interpolation interpolation, std::vector<float> times,
                             std::vector<float> values, int components) {
        animation.samplers.push_back({interpolation, std::move(times), std::move(values), components});
        scene::AnimationChannel c;
        c.sampler = int(animation.samplers.size() - 1);
        c.node = -1;
        c.path = scene::AnimationPath::Property;
        c.property = {field, 0, -1};
        animation.channels.push_back(c);
    };
    using scene::AnimatedField;
    using scene::Interpolation;
    channel(AnimatedField::Transmission, Interpolation::Linear, {0.0f, 1.0f}, {0.0f, 0.9f}, 1);
    channel(AnimatedField::Thickness, Interpolation::Linear, {0.0f, 1.0f}, {0.5f, 0.25f}, 1);
    channel(AnimatedField::AttenuationDistance, Interpolation::Step, {0.0f, 0.5f}, {0.25f, 0.5f}, 1);
    channel(AnimatedField::AttenuationColor, Interpolation::Linear, {0.0f, 1.0f}, {0.9f, 0.5f, 0.2f, 0.5f, 0.9f, 0.9f}, 3);
    s.animations.push_back(std::move(animation));
    const dvec3 L(3.0);
    addBackdrop(s, glm::vec3(L), false);
    const render::View view = frontView();
    render::Renderer renderer;
    renderer.setScene(s);
    render::GpuScene gpu(s); // the lists and the shadow rule, posed alongside
    std::vector<render::DrawProgram> programs(size_t(gpu.materialCount()));
    for (const double t : {0.25, 0.75, -1.0, 0.0}) {
        const bool rest = t < 0.0;
        renderer.setPose(rest ? -1 : 0, float(std::max(t, 0.0)));
        gpu.setPose(rest ? -1 : 0, float(std::max(t, 0.0)));
        renderer.render(view, test::radianceFrame(kSize, kSize, test::Brdf::Exact));
        const ImageFloat image = renderer.readRadiance();
        const double u = std::max(t, 0.0);
        const double factor = rest ? 0.9 : 0.9 * u, thick = rest ? 0.5 : 0.5 - 0.25 * u;
        const double d = rest || t < 0.5 ? 0.25 : 0.5;
        const dvec3 c = rest ? dvec3(0.9, 0.5, 0.2) : glm::mix(dvec3(0.9, 0.5, 0.2), dvec3(0.5, 0.9, 0.9), u);
        const QuadVolume volume{{factor * 128.0 / 255.0, factor}, {thick, thick * 64.0 / 255.0}, c, d};
        int tested = 0, failures = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const auto texelHit = quadTexel(view, x, y);
                if (!texelHit) continue;
                const dvec3 want = transmittedThroughQuad(texelHit->first, texelHit->second, volume, L);
                const dvec3 got = pixel(image, x, y);
                ++tested;
                for (int ch = 0; ch < 3; ++ch)
                    if (std::abs(got[ch] - want[ch]) > kTransmissionRelative * want[ch] + kAbsolute && failures++ < 5)
                        ADD_FAILURE() << "t " << t << " pixel (" << x << ", " << y << ") channel " << ch << ": " << got[ch]
                                      << ", expected T (1 - F) c^(t/d) L = " << want[ch];
            }
        EXPECT_EQ(failures, 0) << "t " << t;
        EXPECT_GT(tested, 1000);
        std::printf("animated transmission at %s: %d pixels compared, %d channels off\n", rest ? "rest" : std::to_string(t).c_str(),
                    tested, failures);
        const render::DrawList casters = render::DrawList::build(gpu, view.view, view.projection * view.view,
                                                                 render::DrawFilter::ShadowCasters, programs);
        const render::DrawList transmissive = render::DrawList::build(gpu, view.view, view.projection * view.view,
                                                                      render::DrawFilter::Transmissive, programs);
        const auto quadIn = [&](const render::DrawList& list) {
            return std::count_if(list.commands().begin(), list.commands().end(), [](const render::DrawCommand& c) { return c.material == 0; });
        };
        // Its transmission texture: a caster at every factor, cut out texel by texel from 0.5 up.
        EXPECT_EQ(quadIn(casters), 1) << "t " << t;
        EXPECT_EQ(render::transmissionCutout(gpu.materials()[0]), factor >= render::kTransmissionShadowLimit) << "t " << t;
        EXPECT_EQ(quadIn(transmissive), factor > 0.0 ? 1 : 0) << "t " << t;
    }
}

// A smooth sphere of IOR 1 (no interface: F0 = 0) bends nothing: it is invisible but for its
// reflection, which is Schlick's F = (1 − n·v)^5 at grazing angles. Each pixel is
// (1 − F) × the checker's own pixel; where F < 1% (n·v > 0.6) it is the checker's pixel.
TEST_F(GlTest, TransparencySphereOfIorOneIsInvisible)
{
    scene::Scene reference;
    addBackdrop(reference, glm::vec3(1.0f), true, -3.0f);
    scene::Scene withSphere = reference;
    scene::addShape(withSphere, scene::makeUvSphere(1.0f, 256, 128), glass(1.0f, 1.0f, 2.0f), glm::mat4(1.0f), "sphere");
    const render::View view = frontView(5.0f);
    const ImageFloat behind = renderScene(reference, view, test::radianceFrame(kSize, kSize, test::Brdf::Exact));
    const ImageFloat through = renderScene(withSphere, view, test::radianceFrame(kSize, kSize, test::Brdf::Exact));
    int tested = 0, invisible = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const Ray ray = pixelRay(view, x, y, kSize, kSize);
            const double b = glm::dot(ray.origin, ray.direction);
            const double disc = b * b - (glm::dot(ray.origin, ray.origin) - 1.0);
            if (disc <= 0.0) continue;
            const dvec3 p = ray.origin + ray.direction * (-b - std::sqrt(disc));
            const double NoV = glm::dot(glm::normalize(p), -ray.direction);
            if (NoV < 0.3) continue; // silhouettes straddle facets and background
            ++tested;
            const double F = std::pow(1.0 - NoV, 5.0);
            const dvec3 ref = pixel(behind, x, y), got = pixel(through, x, y);
            for (int ch = 0; ch < 3; ++ch) {
                const double want = (1.0 - F) * ref[ch];
                ASSERT_LE(std::abs(got[ch] - want), 0.02 * want + kAbsolute)
                    << "pixel (" << x << ", " << y << ") n.v " << NoV << " channel " << ch << ": " << got[ch] << ", expected " << want;
                if (NoV > 0.6) {
                    ASSERT_LE(std::abs(got[ch] - ref[ch]), 0.015 * ref[ch] + kAbsolute) << "visible at n.v " << NoV;
                }
            }
            if (NoV > 0.6) ++invisible;
        }
    EXPECT_GT(tested, 1500);
    EXPECT_GT(invisible, 1000);
}

namespace {

// Two blended quads crossing each other along the Y axis, ±35° about it: on one side of the
// axis the first is in front, on the other the second. Their bounds share a centre, so the
// sorted list draws them in scene order whatever it is.
struct Layer {
    glm::dmat4 frame;
    dvec3 color;
    double alpha;
};

std::vector<Layer> crossedQuads()
{
    auto at = [](float degrees) { return glm::dmat4(facingZ(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0, 1, 0)))); };
    return {{at(35.0f), {1.0, 0.15, 0.1}, 0.6}, {at(-35.0f), {0.1, 0.3, 1.0}, 0.5}};
}

scene::Scene crossedQuadScene(bool reversed)
{
    scene::Scene s;
    std::vector<Layer> layers = crossedQuads();
    if (reversed) std::swap(layers[0], layers[1]);
    for (const Layer& layer : layers) {
        scene::Material m;
        m.name = "layer";
        m.baseColorFactor = glm::vec4(glm::vec3(layer.color), float(layer.alpha));
        m.alphaMode = scene::AlphaMode::Blend;
        m.doubleSided = true;
        m.shading.model = scene::ShadingModel::Unlit; // its colour exactly, no light needed
        scene::addShape(s, scene::makePlane(2.0f), m, glm::mat4(layer.frame), "layer");
    }
    return s;
}

const glm::dvec3 kBackground(0.2, 0.25, 0.3);

/// McGuire & Bavoil 2013, eq. 7: the weight of a layer at view depth z.
double oitWeight(double z, double alpha)
{
    const double d = std::abs(z);
    return alpha * std::clamp(10.0 / (1e-5 + std::pow(d / 5.0, 2.0) + std::pow(d / 200.0, 6.0)), 1e-2, 3e3);
}

} // namespace

// Weighted blended OIT: the crossed quads give the same image in either scene order (within
// 0.1%: only the order of float additions differs), every pixel the paper's weighted mean
// over the background (1%), with one sample and with four. Sorted blending differs between
// the orders exactly where the quads overlap, each order matching "over" in its draw order.
TEST_F(GlTest, TransparencyOitIsOrderIndependent)
{
    const render::View view = frontView(5.0f);
    render::FrameSettings settings = test::radianceFrame(kSize, kSize, test::Brdf::Exact);
    settings.background = glm::vec3(kBackground);
    auto shot = [&](bool reversed, render::Transparency transparency, int msaa) {
        render::FrameSettings s = settings;
        s.transparency = transparency;
        s.msaa = msaa;
        return renderScene(crossedQuadScene(reversed), view, s);
    };
    const ImageFloat oitForward = shot(false, render::Transparency::Oit, 1);
    const ImageFloat oitReversed = shot(true, render::Transparency::Oit, 1);
    const ImageFloat oitMsaa = shot(true, render::Transparency::Oit, 4);
    const ImageFloat sortedForward = shot(false, render::Transparency::Sorted, 1);
    const ImageFloat sortedReversed = shot(true, render::Transparency::Sorted, 1);

    const std::vector<Layer> layers = crossedQuads();
    int overlap = 0, single = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const Ray ray = pixelRay(view, x, y, kSize, kSize);
            // Layers hit, clear of the quads' edges and of their crossing (where depth ties).
            std::vector<std::pair<const Layer*, dvec3>> hits;
            bool nearEdge = false;
            for (const Layer& layer : layers) {
                if (const auto p = hitQuad(ray, layer.frame, 1.0)) {
                    if (!hitQuad(ray, layer.frame, 0.97)) nearEdge = true;
                    hits.push_back({&layer, *p});
                } else if (hitQuad(ray, layer.frame, 1.03)) {
                    nearEdge = true;
                }
            }
            if (nearEdge || (hits.size() == 2 && std::abs(hits[0].second.z - hits[1].second.z) < 0.05)) continue;
            // The weighted mean: Σ C_i a_i w_i / Σ a_i w_i, C_i premultiplied, over the background.
            dvec3 sum(0.0);
            double weights = 0.0, revealage = 1.0;
            for (const auto& [layer, p] : hits) {
                const double z = p.z - 5.0; // view space: the camera at z = 5 looks down -z
                const double w = oitWeight(z, layer->alpha);
                sum += layer->color * layer->alpha * w;
                weights += layer->alpha * w;
                revealage *= 1.0 - layer->alpha;
            }
            const dvec3 want = hits.empty() ? kBackground : sum / weights * (1.0 - revealage) + kBackground * revealage;
            const dvec3 a = pixel(oitForward, x, y), b = pixel(oitReversed, x, y), m = pixel(oitMsaa, x, y);
            for (int ch = 0; ch < 3; ++ch) {
                ASSERT_LE(std::abs(a[ch] - b[ch]), 1e-3 * std::max(a[ch], 1.0)) << "OIT depends on the order at (" << x << ", " << y << ")";
                ASSERT_LE(std::abs(a[ch] - want[ch]), 0.01 * want[ch] + kAbsolute)
                    << "OIT at (" << x << ", " << y << ") channel " << ch << ": " << a[ch] << ", weighted mean " << want[ch];
                ASSERT_LE(std::abs(m[ch] - want[ch]), 0.01 * want[ch] + kAbsolute) << "OIT with 4 samples at (" << x << ", " << y << ")";
            }
            // Sorted: "over" in draw order (scene order; the second drawn on top).
            auto over = [&](bool reversed) {
                dvec3 c = kBackground;
                for (int i = 0; i < 2; ++i) {
                    const Layer& layer = layers[size_t(reversed ? 1 - i : i)];
                    for (const auto& hit : hits)
                        if (hit.first == &layer) c = layer.color * layer.alpha + c * (1.0 - layer.alpha);
                }
                return c;
            };
            const dvec3 sf = pixel(sortedForward, x, y), sr = pixel(sortedReversed, x, y);
            const dvec3 wantForward = over(false), wantReversed = over(true);
            for (int ch = 0; ch < 3; ++ch) {
                ASSERT_LE(std::abs(sf[ch] - wantForward[ch]), 0.01 * wantForward[ch] + kAbsolute) << "sorted at (" << x << ", " << y << ")";
                ASSERT_LE(std::abs(sr[ch] - wantReversed[ch]), 0.01 * wantReversed[ch] + kAbsolute) << "sorted at (" << x << ", " << y << ")";
            }
            if (hits.size() == 2) {
                ++overlap;
                EXPECT_GT(glm::length(sf - sr), 0.05) << "sorted blending must depend on the order where the quads overlap";
            } else if (hits.size() == 1) {
                ++single;
            }
        }
    EXPECT_GT(overlap, 300);
    EXPECT_GT(single, 300);
}

// -- one blended mesh that overlaps itself ----------------------------------------------------

namespace {

/// Unlit, coloured by its vertices: a pixel is its surface's colour exactly.
scene::Material blendedUnlit(float alpha, bool doubleSided)
{
    scene::Material m;
    m.name = "blended";
    m.baseColorFactor = glm::vec4(1.0f, 1.0f, 1.0f, alpha);
    m.alphaMode = scene::AlphaMode::Blend;
    m.doubleSided = doubleSided;
    m.shading.model = scene::ShadingModel::Unlit;
    return m;
}

/// Two squares facing +Z in one primitive, the near one (z = 0.5, x in [-1, 0.6]) before the
/// far one (z = -0.5, x in [-0.6, 1]) in index order: drawn in that order without depth
/// writes, the far one covers the near one where they overlap.
struct Square {
    double z, xMin, xMax;
    dvec3 color;
};
const Square kSquares[2] = {{0.5, -1.0, 0.6, {1.0, 0.2, 0.1}}, {-0.5, -0.6, 1.0, {0.1, 0.3, 1.0}}};

scene::Primitive squaresPrimitive(float colourAlpha = 1.0f)
{
    scene::Primitive p;
    for (const Square& q : kSquares) {
        const uint32_t base = uint32_t(p.vertices.size());
        const glm::vec2 corners[4] = {{q.xMin, -0.8}, {q.xMax, -0.8}, {q.xMax, 0.8}, {q.xMin, 0.8}};
        for (const glm::vec2& c : corners) {
            scene::Vertex v;
            v.position = glm::vec3(c, float(q.z));
            v.normal = glm::vec3(0, 0, 1);
            v.color = glm::vec4(glm::vec3(q.color), colourAlpha);
            p.vertices.push_back(v);
            p.bounds.extend(v.position);
        }
        p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    p.hasColors = true;
    return p;
}

} // namespace

// A blended material whose alpha is 1 everywhere covers what is behind it: every layer sorted,
// the frontmost wins. It is drawn as opaque (render/GpuScene.h, MaterialBinding::alphaMode), so
// one mesh that overlaps itself shows its near surface, not whichever triangle came last (the
// pmndrs bunny, a closed double-sided BLEND model of alpha 1, showed its back faces in patches).
// Each pixel against a ray test of the two squares. Its alpha set to 0.5 at run time (the
// viewer's material panel), the mesh blends again, "over" in index order; set back to 1 it is
// opaque again. A texel or a vertex colour below 1 keeps it blended.
TEST_F(GlTest, TransparencyBlendedWithAlphaOneIsDrawnOpaque)
{
    const render::View view = frontView(5.0f);
    render::FrameSettings settings = test::radianceFrame(kSize, kSize, test::Brdf::Exact);
    settings.background = glm::vec3(kBackground);
    scene::Scene s;
    scene::addShape(s, squaresPrimitive(), blendedUnlit(1.0f, false), glm::mat4(1.0f), "squares");
    render::Renderer renderer;
    renderer.setScene(s);
    auto shot = [&] {
        renderer.render(view, settings);
        return renderer.readRadiance();
    };
    const ImageFloat opaque = shot();
    renderer.setMaterialParameter(0, render::MaterialParameter::BaseColor, glm::vec4(1.0f, 1.0f, 1.0f, 0.5f));
    const ImageFloat half = shot();
    renderer.setMaterialParameter(0, render::MaterialParameter::BaseColor, glm::vec4(1.0f));
    const ImageFloat again = shot();

    int overlap = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const Ray ray = pixelRay(view, x, y, kSize, kSize);
            std::vector<const Square*> hits; // in index order
            bool nearEdge = false;
            for (const Square& q : kSquares) {
                const double t = (q.z - ray.origin.z) / ray.direction.z;
                const dvec3 p = ray.origin + t * ray.direction;
                const double inside = std::min({p.x - q.xMin, q.xMax - p.x, 0.8 - std::abs(p.y)});
                if (std::abs(inside) < 0.03) nearEdge = true;
                if (inside > 0.0) hits.push_back(&q);
            }
            if (nearEdge) continue;
            const dvec3 front = hits.empty() ? kBackground : hits[0]->color; // the near square is first
            dvec3 over = kBackground;
            for (const Square* q : hits) over = 0.5 * q->color + 0.5 * over;
            const dvec3 a = pixel(opaque, x, y), h = pixel(half, x, y), b = pixel(again, x, y);
            for (int ch = 0; ch < 3; ++ch) {
                ASSERT_LE(std::abs(a[ch] - front[ch]), 0.01 * front[ch] + kAbsolute)
                    << "alpha 1 at (" << x << ", " << y << ") channel " << ch << ": " << a[ch] << ", the front surface " << front[ch];
                ASSERT_LE(std::abs(h[ch] - over[ch]), 0.01 * over[ch] + kAbsolute)
                    << "alpha 0.5 at (" << x << ", " << y << ") channel " << ch << ": " << h[ch] << ", over in index order " << over[ch];
                ASSERT_LE(std::abs(b[ch] - front[ch]), 0.01 * front[ch] + kAbsolute) << "alpha 1 again at (" << x << ", " << y << ")";
            }
            if (hits.size() == 2) ++overlap;
        }
    EXPECT_GT(overlap, 500);

    // What keeps it blended: the factor, a base colour texel, a vertex colour below 1.
    auto drawnAs = [](const scene::Scene& scene) {
        const render::GpuScene gpu(scene);
        return gpu.materials()[size_t(gpu.primitives()[0].material)].alphaMode; // the vertex colours' copy
    };
    EXPECT_EQ(drawnAs(s), scene::AlphaMode::Opaque);
    scene::Scene factor;
    scene::addShape(factor, squaresPrimitive(), blendedUnlit(0.999f, false), glm::mat4(1.0f), "squares");
    EXPECT_EQ(drawnAs(factor), scene::AlphaMode::Blend);
    scene::Scene colours;
    scene::addShape(colours, squaresPrimitive(0.999f), blendedUnlit(1.0f, false), glm::mat4(1.0f), "squares");
    EXPECT_EQ(drawnAs(colours), scene::AlphaMode::Blend);
    for (const uint8_t texelAlpha : {uint8_t(255), uint8_t(254)}) {
        scene::Scene textured;
        scene::Image image;
        image.width = image.height = 2;
        image.pixels = {255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, texelAlpha};
        textured.images.push_back(image);
        scene::Material m = blendedUnlit(1.0f, false);
        m.baseColorTexture.image = 0;
        scene::addShape(textured, squaresPrimitive(), m, glm::mat4(1.0f), "squares");
        EXPECT_EQ(drawnAs(textured), texelAlpha == 255 ? scene::AlphaMode::Opaque : scene::AlphaMode::Blend);
    }
}

// A closed double-sided blended mesh of alpha 0.5: a cube whose faces have their own colours,
// seen from a corner, in makeCube's face order (+X, −X, +Y, −Y, +Z, −Z: back faces drawn after
// front ones). Its back faces are drawn first, then its front faces, so every pixel is the
// front face over the back face over the background ("over", Porter–Duff), the faces found by an
// exact ray–box test.
TEST_F(GlTest, TransparencyDoubleSidedBlendDrawsBackFacesFirst)
{
    constexpr double kHalf = 0.6, kAlpha = 0.5;
    const render::View view =
        render::lookAtView({2.2f, 1.6f, 3.0f}, {0, 0, 0}, {0, 1, 0}, glm::radians(30.0f), 1.0f, 0.1f, 20.0f);
    render::FrameSettings settings = test::radianceFrame(kSize, kSize, test::Brdf::Exact);
    settings.background = glm::vec3(kBackground);
    auto faceColor = [](const dvec3& n) { return dvec3(0.5) + 0.45 * n; };
    scene::Primitive cube = scene::makeCube(float(kHalf));
    for (scene::Vertex& v : cube.vertices) v.color = glm::vec4(glm::vec3(faceColor(dvec3(v.normal))), 1.0f);
    cube.hasColors = true;
    scene::Scene s;
    scene::addShape(s, std::move(cube), blendedUnlit(float(kAlpha), true), glm::mat4(1.0f), "cube");
    const ImageFloat image = renderScene(s, view, settings);

    int twoLayers = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const Ray ray = pixelRay(view, x, y, kSize, kSize);
            // Slabs: the entry face is the axis of the largest near t, the exit the smallest far t.
            double tNear = -1e30, tFar = 1e30;
            int entryAxis = 0, exitAxis = 0;
            for (int axis = 0; axis < 3; ++axis) {
                const double t0 = (-kHalf - ray.origin[axis]) / ray.direction[axis];
                const double t1 = (kHalf - ray.origin[axis]) / ray.direction[axis];
                if (std::min(t0, t1) > tNear) tNear = std::min(t0, t1), entryAxis = axis;
                if (std::max(t0, t1) < tFar) tFar = std::max(t0, t1), exitAxis = axis;
            }
            dvec3 want = kBackground;
            if (tNear < tFar) {
                const dvec3 entry = ray.origin + tNear * ray.direction, exit = ray.origin + tFar * ray.direction;
                // Clear of the cube's edges, where a pixel may be two faces.
                auto nearEdge = [&](const dvec3& p, int axis) {
                    for (int other = 0; other < 3; ++other)
                        if (other != axis && kHalf - std::abs(p[other]) < 0.03) return true;
                    return false;
                };
                if (nearEdge(entry, entryAxis) || nearEdge(exit, exitAxis)) continue;
                dvec3 n(0.0);
                n[entryAxis] = entry[entryAxis] > 0.0 ? 1.0 : -1.0;
                const dvec3 front = faceColor(n);
                n = dvec3(0.0);
                n[exitAxis] = exit[exitAxis] > 0.0 ? 1.0 : -1.0;
                const dvec3 back = faceColor(n);
                want = kAlpha * front + (1.0 - kAlpha) * (kAlpha * back + (1.0 - kAlpha) * kBackground);
                ++twoLayers;
            } else if (tFar > tNear - 0.05 && tNear < 1e29) {
                continue; // grazing the silhouette
            }
            const dvec3 got = pixel(image, x, y);
            for (int ch = 0; ch < 3; ++ch)
                ASSERT_LE(std::abs(got[ch] - want[ch]), 0.01 * want[ch] + kAbsolute)
                    << "at (" << x << ", " << y << ") channel " << ch << ": " << got[ch] << ", front over back " << want[ch];
        }
    EXPECT_GT(twoLayers, 1000);
}

// The shadow rule (render/GpuScene.h): opaque surfaces and those that let less than half the
// light through cast; blended ones and those of transmission 0.5 and above do not. A blended
// material of alpha 1 everywhere is drawn opaque, and casts none still (ShadowsSpot's lamp).
// Those that let light through — blended, or of transmission 0.5 and above — tint the shadows
// (render::tintsShadow: the tint map), except a blended one of alpha 1 everywhere, drawn opaque:
// it casts nothing still.
TEST_F(GlTest, TransparencyShadowCastersFollowTheRule)
{
    scene::Scene s;
    struct Kind {
        const char* name;
        scene::AlphaMode alphaMode;
        float transmission;
        bool casts;
        float alpha;
        bool tints;
    } kinds[] = {{"opaque", scene::AlphaMode::Opaque, 0.0f, true, 1.0f, false},
                 {"blended", scene::AlphaMode::Blend, 0.0f, false, 0.5f, true},
                 {"blended of alpha 1 (drawn opaque, casts none)", scene::AlphaMode::Blend, 0.0f, false, 1.0f, false},
                 {"tinted glass", scene::AlphaMode::Opaque, 0.3f, true, 1.0f, false},
                 {"clear glass", scene::AlphaMode::Opaque, 0.5f, false, 1.0f, true},
                 {"blended glass", scene::AlphaMode::Blend, 0.2f, false, 0.5f, true},
                 {"clear glass with a transmission texture (cut out per texel)", scene::AlphaMode::Opaque, 1.0f, true, 1.0f, true},
                 {"blended glass with a transmission texture", scene::AlphaMode::Blend, 1.0f, false, 0.5f, true}};
    s.images.push_back({"transmission", 1, 1, 4, {255, 255, 255, 255}});
    for (const Kind& k : kinds) {
        scene::Material m;
        m.name = k.name;
        m.alphaMode = k.alphaMode;
        m.baseColorFactor.a = k.alpha;
        m.transmissionFactor = k.transmission;
        if (std::string_view(k.name).find("texture") != std::string_view::npos) m.transmissionTexture.image = 0;
        scene::addShape(s, scene::makeCube(0.5f), m, glm::mat4(1.0f), k.name);
    }
    const render::GpuScene gpu(s);
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    const glm::mat4 viewProjection = glm::perspective(glm::radians(40.0f), 1.0f, 0.1f, 20.0f) * view;
    std::vector<render::DrawProgram> programs(size_t(gpu.materialCount()));
    const render::DrawList casters = render::DrawList::build(gpu, view, viewProjection, render::DrawFilter::ShadowCasters, programs);
    std::vector<int> casting;
    for (const render::DrawCommand& c : casters.commands()) casting.push_back(c.material);
    std::sort(casting.begin(), casting.end());
    std::vector<int> expected;
    for (size_t i = 0; i < std::size(kinds); ++i)
        if (kinds[i].casts) expected.push_back(int(i));
    EXPECT_EQ(casting, expected);
    const render::DrawList tinters = render::DrawList::build(gpu, view, viewProjection, render::DrawFilter::ShadowTinters, programs);
    std::vector<int> tinting, expectedTinting;
    for (const render::DrawCommand& c : tinters.commands()) tinting.push_back(c.material);
    std::sort(tinting.begin(), tinting.end());
    for (size_t i = 0; i < std::size(kinds); ++i)
        if (kinds[i].tints) expectedTinting.push_back(int(i));
    EXPECT_EQ(tinting, expectedTinting);
    // Transmissive draws have their own list (drawn after the opaque frame is copied), blended or not.
    const render::DrawList transmissive = render::DrawList::build(gpu, view, viewProjection, render::DrawFilter::Transmissive, programs);
    EXPECT_EQ(transmissive.commands().size(), 5u);
    const render::DrawList opaque = render::DrawList::build(gpu, view, viewProjection, render::DrawFilter::Opaque, programs);
    EXPECT_EQ(opaque.commands().size(), 2u);
    const render::DrawList blended = render::DrawList::build(gpu, view, viewProjection, render::DrawFilter::Blended, programs);
    EXPECT_EQ(blended.commands().size(), 1u);
}

// -- dispersion ------------------------------------------------------------------------------

// KHR_materials_dispersion: a volume slab (thickness 1, ior 1.5, dispersion 20: V_d = 1, far
// beyond any glass, so that the channels part by a few pixels) tilted 35° about the vertical axis,
// in front of an emissive backdrop whose red and green rise and whose blue falls from left to
// right. The CPU traces each pixel's ray to the slab and refracts it (Snell's law, exactly) with
// each channel's own index of refraction, the extension's n = ior ∓ (ior − 1) × 0.025 ×
// dispersion (green: the ior), leaves the volume after its thickness and reads that channel of
// the frame without the slab where the exit point projects (bilinear at pixel centres); times
// 1 − F(n·v), Schlick with F0 = 0.04. Tolerance: 1 % + 2e-3 as the other transmission tests.
// Broken on purpose (the DISPERSION variant reading green's ray for every channel): red is off by
// 7.7 % at worst (0.297 for 0.322), far outside. Dispersion 0 must match green's ray in all three.
TEST_F(GlTest, TransparencyDispersionRefractsEachChannelWithItsOwnIor)
{
    constexpr int kWide = 128;
    scene::Scene reference;
    {
        scene::Material m;
        m.name = "gradient backdrop";
        m.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        m.roughnessFactor = 1.0f;
        m.emissiveFactor = glm::vec3(2.0f);
        scene::Image image;
        image.name = "gradient";
        image.width = 64;
        image.height = 1;
        for (int x = 0; x < 64; ++x) {
            const uint8_t texel[4] = {uint8_t(60 + 3 * x), uint8_t(20 + 2 * x), uint8_t(250 - 3 * x), 255};
            image.pixels.insert(image.pixels.end(), texel, texel + 4);
        }
        reference.images.push_back(std::move(image));
        reference.samplers.push_back(scene::Sampler{});
        m.emissiveTexture.image = 0;
        m.emissiveTexture.sampler = 0;
        scene::addShape(reference, scene::makePlane(4.0f), m, facingZ(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -2.0f))),
                        "backdrop");
    }
    const double ior = 1.5, thickness = 1.0;
    const glm::mat4 slab = glm::rotate(glm::mat4(1.0f), glm::radians(35.0f), glm::vec3(0, 1, 0)) *
                           glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0));
    const render::View view = frontView();
    render::FrameSettings settings = test::radianceFrame(kSize, kSize, test::Brdf::Exact);
    settings.width = settings.height = kWide;
    const ImageFloat behind = renderScene(reference, view, settings);
    auto bilinear = [&](glm::dvec2 uv, int channel) {
        const double fx = uv.x * kWide - 0.5, fy = (1.0 - uv.y) * kWide - 0.5; // row 0 at the top
        const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
        const double ax = fx - x0, ay = fy - y0;
        auto at = [&](int x, int y) { return pixel(behind, std::clamp(x, 0, kWide - 1), std::clamp(y, 0, kWide - 1))[channel]; };
        return (1 - ay) * ((1 - ax) * at(x0, y0) + ax * at(x0 + 1, y0)) + ay * ((1 - ax) * at(x0, y0 + 1) + ax * at(x0 + 1, y0 + 1));
    };
    const glm::dmat4 viewProjection = glm::dmat4(view.projection * view.view);
    const dvec3 normal = glm::normalize(dvec3(glm::dmat4(slab)[1]));

    for (double dispersion : {20.0, 0.0}) {
        SCOPED_TRACE(dispersion);
        scene::Scene s = reference;
        scene::Material m = glass(1.0f, float(ior), float(thickness));
        m.dispersion = float(dispersion);
        scene::addShape(s, scene::makePlane(1.2f), m, slab, "dispersive slab");
        const ImageFloat image = renderScene(s, view, settings);
        const double halfSpread = (ior - 1.0) * 0.025 * dispersion;
        const dvec3 iors(std::max(ior - halfSpread, 1.0), ior, ior + halfSpread);
        int tested = 0;
        double worst = 0.0, redShift = 0.0;
        for (int y = 0; y < kWide; ++y)
            for (int x = 0; x < kWide; ++x) {
                const Ray ray = pixelRay(view, x, y, kWide, kWide);
                const auto hit = hitQuad(ray, glm::dmat4(slab), 0.55);
                if (!hit) continue;
                const dvec3 v = -ray.direction;
                const double NoV = glm::dot(normal, v);
                const double F = 0.04 + 0.96 * std::pow(1.0 - NoV, 5.0);
                // Where a ray refracted with index n leaves the volume, on screen.
                auto exitUv = [&](double n) {
                    const dvec3 direction = glm::refract(ray.direction, normal, 1.0 / n);
                    const glm::dvec4 clip = viewProjection * glm::dvec4(*hit + glm::normalize(direction) * thickness, 1.0);
                    return glm::dvec2(clip) / clip.w * 0.5 + 0.5;
                };
                bool inside = true;
                dvec3 want(0.0);
                for (int c = 0; c < 3; ++c) {
                    const glm::dvec2 uv = exitUv(iors[c]);
                    inside = inside && uv.x > 0.02 && uv.x < 0.98 && uv.y > 0.02 && uv.y < 0.98;
                    want[c] = (1.0 - F) * bilinear(uv, c);
                }
                redShift = std::max(redShift, std::abs(exitUv(iors[0]).x - exitUv(ior).x) * kWide);
                if (!inside) continue;
                ++tested;
                const dvec3 got = pixel(image, x, y);
                for (int c = 0; c < 3; ++c) {
                    worst = std::max(worst, std::abs(got[c] - want[c]) / want[c]);
                    ASSERT_LE(std::abs(got[c] - want[c]), kTransmissionRelative * want[c] + kAbsolute)
                        << "pixel (" << x << ", " << y << ") channel " << c << ": " << got[c] << ", expected " << want[c]
                        << " (ior " << iors[c] << ")";
                }
            }
        EXPECT_GT(tested, 1500);
        std::printf("dispersion %.0f: %d pixels, worst %.3f %% of the expected value, red's exit up to %.2f px from green's\n",
                    dispersion, tested, 100.0 * worst, redShift);
    }
}
