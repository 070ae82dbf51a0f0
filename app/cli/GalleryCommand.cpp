// specula gallery: the same scene once per shading model, then its blended surfaces once as
// "fade" and once as "newell-newell-sancha" (highlights kept, docs/transparency.md), and with
// --variants once per BRDF term, in one labelled contact sheet.
#include <filesystem>
#include <optional>

#include "Commands.h"
#include "core/Error.h"
#include "core/ImageIO.h"
#include "core/Log.h"
#include "gl/Debug.h"
#include "platform/Context.h"
#include "shading/ContactSheet.h"

namespace specula::cli {
namespace {

const char* modelCaption(scene::ShadingModel model)
{
    switch (model) {
    case scene::ShadingModel::Pbr: return "pbr (Cook-Torrance, glTF)";
    case scene::ShadingModel::Unlit: return "unlit";
    case scene::ShadingModel::Flat: return "flat (Warnock 1969)";
    case scene::ShadingModel::Gouraud: return "gouraud (1971)";
    case scene::ShadingModel::Phong: return "phong (1975)";
    case scene::ShadingModel::BlinnPhong: return "blinn-phong (1977)";
    case scene::ShadingModel::Doom: return "doom (1993)";
    }
    return "?";
}

} // namespace

int runGallery(const GalleryArgs& args)
{
    const std::filesystem::path output = args.output;
    if (args.frame.allCameras) throw Error("--camera all is for render (one image per camera); gallery shows one view: give an index");
    checkOutputPath(output);
    scene::SceneDocument document = setup::loadSceneOrBuiltin(args.scene, args.frame.load, args.frame.lights);
    setup::FrameOptions options = args.frame;
    // Tiles, not full frames: small by default.
    if (!options.width) options.width = 480;
    if (!options.height) options.height = 320;
    const render::FrameSettings base = setup::resolveSettings(document, options);
    const std::optional<render::EnvironmentMap> environment = setup::loadEnvironment(document, options);
    // A scene without lights gets the default rig even under an environment (which `render`
    // would light it with alone): the classic models take no specular light from an
    // environment, and without a light their tiles would all show the same ambient term.
    const setup::AnimationChoice animation = setup::resolveAnimation(document.scene, options);
    const render::View view = setup::prepareView(document, options, base, nullptr, /*hasEnvironment=*/false, animation);

    auto context = platform::Context::createHeadless();
    gl::DebugMonitor debug;
    render::Renderer renderer;
    renderer.setCacheDirectory(setup::cacheDirectory(options));
    renderer.setScene(document.scene);
    renderer.setPose(animation.index, animation.seconds);
    renderer.setVariant(setup::resolveVariant(document.scene, options));
    if (environment) renderer.setEnvironment(*environment, setup::resolveBakeSettings(options), setup::cacheDirectory(options));

    std::vector<render::SheetTile> tiles;
    auto shoot = [&](std::string label, const scene::MaterialShading& shading, std::optional<scene::BlendMode> blend = {}) {
        render::FrameSettings settings = base;
        settings.materialOverride = shading;
        settings.blendModeOverride = blend;
        renderer.render(view, settings);
        tiles.push_back({std::move(label), renderer.readImage()});
        log::info("gallery: {}", tiles.back().label);
    };
    for (int m = 0; m < scene::kShadingModelCount; ++m) {
        scene::MaterialShading shading = base.materialOverride;
        shading.model = scene::ShadingModel(m);
        shoot(modelCaption(*shading.model), shading);
    }
    // Blended surfaces (the demo's glass sphere) with alpha as coverage, then with their
    // specular light and emission kept whole (Newell, Newell and Sancha 1972; Filament's "transparent").
    scene::MaterialShading pbrShading = base.materialOverride;
    pbrShading.model = scene::ShadingModel::Pbr;
    shoot("fade (glTF: alpha is coverage)", pbrShading, scene::BlendMode::Fade);
    shoot("newell-newell-sancha (1972)", pbrShading, scene::BlendMode::Transparent);
    if (args.variants) {
        scene::MaterialShading pbr = base.materialOverride;
        pbr.model = scene::ShadingModel::Pbr;
        for (auto d : {scene::BrdfDistribution::GGX, scene::BrdfDistribution::Beckmann, scene::BrdfDistribution::BlinnPhong}) {
            scene::MaterialShading s = pbr;
            s.distribution = d;
            shoot(std::string("D ") + scene::brdfDistributionName(d), s);
        }
        for (auto g : {scene::BrdfGeometry::SmithGGX, scene::BrdfGeometry::SmithGGXCorrelated, scene::BrdfGeometry::SchlickGGX,
                       scene::BrdfGeometry::Neumann, scene::BrdfGeometry::Kelemen, scene::BrdfGeometry::CookTorrance,
                       scene::BrdfGeometry::Implicit}) {
            scene::MaterialShading s = pbr;
            s.geometry = g;
            shoot(std::string("G ") + scene::brdfGeometryName(g), s);
        }
        for (auto f : {scene::BrdfFresnel::Schlick, scene::BrdfFresnel::SchlickSG, scene::BrdfFresnel::None}) {
            scene::MaterialShading s = pbr;
            s.fresnel = f;
            shoot(std::string("F ") + scene::brdfFresnelName(f), s);
        }
        for (auto fd : {scene::BrdfDiffuse::Lambert, scene::BrdfDiffuse::OrenNayar, scene::BrdfDiffuse::Burley}) {
            scene::MaterialShading s = pbr;
            s.diffuse = fd;
            shoot(std::string("diffuse ") + scene::brdfDiffuseName(fd), s);
        }
    }
    writePng(output, render::makeContactSheet(tiles, args.columns));
    log::info("wrote {} ({} tiles)", output.string(), tiles.size());
    if (debug.errorCount() > 0) {
        std::filesystem::remove(output);
        throw Error("OpenGL reported {} error(s); first: {}", debug.errorCount(), debug.errors().front());
    }
    return 0;
}

} // namespace specula::cli
