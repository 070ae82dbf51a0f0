#include "CommandLine.h"

#include <cmath>
#include <cstdlib>
#include <string>

#include "PostOptions.h"
#include "specula/Version.h"

namespace specula::cli {

namespace {

/// What a file may open and allocate (scene/LoadOptions.h). Sizes take units: 512MiB, 2GB.
void addLoadOptions(CLI::App* command, scene::LoadOptions& load)
{
    command->add_flag("--allow-external-files", load.allowExternalFiles,
                      "let scene files and glTF URIs name files outside their own folder (absolute paths, ..)");
    command->add_option("--max-buffer-bytes", load.limits.maxBufferBytes, "largest glTF buffer (default 2GiB)")
        ->transform(CLI::AsSizeValue(false));
    command->add_option("--max-accessor-count", load.limits.maxAccessorCount,
                        "most elements in one glTF accessor (default 268435456)");
    command->add_option("--max-image-size", load.limits.maxImageSize, "most pixels along a side of an image (default 32768)")
        ->check(CLI::Range(1, 1 << 30));
    command->add_option("--max-texture-memory", load.limits.maxTextureBytes,
                        "most decoded texture memory of one model (default 2GiB)")
        ->transform(CLI::AsSizeValue(false));
    command->add_option("--max-instances", load.limits.maxInstances,
                        "most EXT_mesh_gpu_instancing instances in one model (default 1048576)");
}

void addFrameOptions(CLI::App* command, setup::FrameOptions& frame)
{
    command->add_option("--width", frame.width, "image width in pixels (default 1280; render: to match the camera's aspectRatio)");
    command->add_option("--height", frame.height, "image height in pixels (default 720; render: to match a width given with a camera's aspectRatio)");
    command->add_option("--msaa", frame.msaa, "samples per pixel: 1 (pixel centre, no anti-aliasing), 2, 4 (default), 8");
    command->add_option("--exposure", frame.exposure, "exposure in EV: the image is multiplied by 2^EV (default 0)");
    command->add_option("--tonemap", frame.tonemap, "none, reinhard, reinhard-ext, aces, neutral (default), agx");
    command->add_option("--brdf-g", frame.brdfG, "masking-shadowing G: smith-ggx (glTF, default), smith-ggx-correlated, schlick-ggx (UE4), neumann, kelemen, cook-torrance, implicit");
    command->add_option("--brdf-d", frame.brdfD, "normal distribution D: ggx (default), beckmann, blinn-phong");
    command->add_option("--brdf-f", frame.brdfF, "Fresnel F: schlick (default), schlick-sg (UE4), none");
    command->add_option("--brdf-diffuse", frame.brdfDiffuse, "diffuse lobe: lambert (default), oren-nayar, burley");
    command->add_option("--shading", frame.shading, "every material's shading model: pbr, unlit, flat, gouraud, phong, blinn-phong, doom");
    command->add_option("--debug-view", frame.debugView,
                        "show one buffer: base-color, normal, roughness, metallic, occlusion, emissive, brdf-d, brdf-g, brdf-f, ssao, bloom, cascades, shadow-atlas, light-count, sheen, anisotropy, iridescence, clearcoat, clearcoat-normal");
    command
        ->add_option_function<std::string>(
            "--camera",
            [&frame](const std::string& value) {
                if (value == "all") {
                    frame.allCameras = true;
                    return;
                }
                size_t used = 0;
                int index = -1;
                try {
                    index = std::stoi(value, &used);
                } catch (const std::exception&) {
                    used = 0;
                }
                if (used != value.size() || index < 0) throw CLI::ValidationError("--camera", "must be a camera index or all (got '" + value + "')");
                frame.camera = index;
            },
            "index of the scene camera to use (default: the first, else framed); render: all = one image per camera")
        ->type_name("INDEX|all");
    command->add_flag("--no-default-lights", frame.noDefaultLights, "never add the default light rig");
    command->add_option("--env", frame.env, "environment: an equirectangular .hdr or .exr, sky (procedural, the default) or none");
    command->add_option("--env-color", frame.envColor, "a constant environment of radiance R,G,B (cd/m²)");
    command->add_option("--env-intensity", frame.envIntensity, "scales the environment (default 1)");
    command->add_option("--env-rotation", frame.envRotation, "turns the environment about +Y, degrees");
    command->add_option("--skybox", frame.skybox, "on (default), off, or blur=R (R = roughness 0..1)");
    command->add_option("--env-sun", frame.envSun,
                        "extract: take the map's sun out as a directional light of the same illuminance, colour and size (it then casts shadows); keep (default)");
    command->add_option("--ibl", frame.ibl,
                        "specular image-based light: split-sum (the default: one fetch) or importance (64-256 filtered samples per pixel, by "
                        "roughness, with the full BRDF, view-dependent; on llvmpipe about 20x the split sum's forward pass: docs/ibl.md)");
    command->add_option("--bake-preset", frame.bakePreset, "default, or reference (the LearnOpenGL tutorial's bake sizes)");
    command->add_option("--energy-compensation", frame.energyCompensation,
                        "multiple-scattering compensation of the specular lobe: on (default) or off (exactly the glTF BRDF)");
    command->add_flag("--no-cache", frame.noCache, "bake the environment even if the bake cache holds it, and do not cache");
    command->add_flag("--gizmos", frame.gizmos, "draw every light as a disc in the light's colour");
    command->add_option("--light-culling", frame.lightCulling,
                        "clustered (default: each pixel evaluates its cluster's lights) or none (every light everywhere)");
    command->add_option("--light-cutoff", frame.lightCutoff,
                        "lights without a range end where their illuminance falls to this fraction of it at 1 m (default 1e-4: 100 m; 0 = infinite)");
    command->add_option("--lod-error", frame.lodPixels,
                        "levels of detail: the largest on-screen error a coarser mesh may make, in pixels (default 0: full detail; docs/performance.md)");
    command->add_option("--transparency", frame.transparency,
                        "order of blended surfaces: sorted (default: back to front per draw) or oit (weighted blended, no order)");
    command->add_option("--lights", frame.lights, "the many-lights scene's number of point lights (default 1024)");
    command->add_option("--animation", frame.animation,
                        "the glTF animation to pose the scene with: its name or index, or none (the rest pose); default: the first");
    command->add_option("--time", frame.time, "seconds into the animation (default 0; past its end: its last pose)");
    command->add_option("--variant", frame.variant,
                        "the glTF material variant (KHR_materials_variants): its name or index, or none (default: the file's materials)");
    addPostOptions(command, frame);
    addLoadOptions(command, frame.load);
}

/// Every value that reads as a number must be a finite one: "--exposure nan" and "--env-intensity
/// 1e999" would otherwise pass every range check (comparisons with NaN are false) and poison the
/// frame. Applied to every option, whatever its type, so that a new flag cannot forget it.
void rejectNonFinite(CLI::App& app)
{
    for (CLI::Option* option : app.get_options()) {
        if (option->get_type_size() == 0) continue; // a flag: no value
        option->check(
            [](const std::string& value) -> std::string {
                const char* begin = value.c_str();
                char* end = nullptr;
                const double number = std::strtod(begin, &end);
                if (end == begin || *end != '\0' || std::isfinite(number)) return {};
                return "'" + value + "' is not a finite number";
            },
            /*description (none in --help)*/ "", "finite");
    }
    for (CLI::App* sub : app.get_subcommands({})) rejectNonFinite(*sub);
}

} // namespace

CommandLine::CommandLine()
{
    app.set_version_flag("--version", std::string("specula ") + versionString());
    app.require_subcommand(1);
    // One line per failure: the first line of CLI11's message plus a pointer to --help.
    app.failure_message([](const CLI::App*, const CLI::Error& e) {
        return std::string("specula: error: ") + e.what() + " (see --help)\n";
    });

    renderCommand = app.add_subcommand("render", "render a scene to an image (PNG, Radiance HDR or OpenEXR)");
    renderCommand->add_option("scene", render.scenes,
                              "one or more .gltf, .glb or .json scenes, or built-ins: demo (default), learnopengl, learnopengl-ibl; "
                              "several are rendered in one process, paying start-up once");
    renderCommand->add_option("-o,--output", render.output,
                              "output image: .png (tone-mapped sRGB), .hdr or .exr (linear radiance x 2^EV); for several images "
                              "a pattern with {scene} (the file's stem or the built-in's name) and {camera} (its index), e.g. out/{scene}-{camera}.png");
    addFrameOptions(renderCommand, render.frame);
    renderCommand->add_option("--print-graph", render.printGraph,
                              "write the frame's graph of passes and resources as Graphviz dot to FILE (- = standard output)");
    renderCommand->add_flag("--stats", render.stats,
                            "print the GPU time of each pass (median of 9 more frames, timer queries) to stdout");

    infoCommand = app.add_subcommand("info", "print the OpenGL vendor, renderer, version and limits");

    benchCommand = app.add_subcommand("bench", "measure start-up and frame times of built-in scenes");
    benchCommand->add_option("--scene", bench.scenes, "scenes to measure (default: demo learnopengl learnopengl-ibl; also many-lights, doom, files)");
    benchCommand->add_option("-o,--output", bench.output, "JSON results file (default bench.json)");
    benchCommand->add_option("--frames", bench.frames, "frames to time per scene (default 60)");
    benchCommand->add_option("--warmup", bench.warmup, "untimed frames first (default 5)");
    addFrameOptions(benchCommand, bench.frame);

    bakeCommand = app.add_subcommand("bake", "bake an environment for image-based lighting into the cache");
    bakeCommand->add_option("env", bake.env, "an equirectangular .hdr or .exr, or sky")->required();
    bakeCommand->add_option("--bake-preset", bake.preset, "default, or reference (the LearnOpenGL tutorial's bake sizes)");
    bakeCommand->add_option("--env-sun", bake.envSun, "extract: bake the map less its sun, as render and view --env-sun extract read it; keep (default)");
    bakeCommand->add_option("--cache-dir", bake.cacheDirectory, "where to write (default: $SPECULA_CACHE_DIR, $XDG_CACHE_HOME/specula or ~/.cache/specula)");

    viewCommand = app.add_subcommand("view", "open a window on a scene, with panels (docs/viewer.md)");
    viewCommand->add_option("scene", view.scene, "a .gltf, .glb or .json scene, or a built-in: demo (default), learnopengl, learnopengl-ibl");
    viewCommand->add_option("--frames", view.frames, "render N frames (after --script), then exit");
    viewCommand->add_option("--screenshot", view.screenshot, "with --frames: write the last frame as PNG");
    viewCommand->add_option("--script", view.script, "replay UI actions from FILE (docs/viewer.md)");
    viewCommand->add_flag("--hide-ui", view.hideUi, "start with the panels hidden (H shows them)");
    addFrameOptions(viewCommand, view.frame);

    galleryCommand = app.add_subcommand("gallery", "render a scene once per shading model into a labelled contact sheet");
    galleryCommand->add_option("scene", gallery.scene, "a .gltf, .glb or .json scene, or a built-in (default: demo)");
    galleryCommand->add_option("-o,--output", gallery.output, "the contact sheet, PNG (default gallery.png)");
    galleryCommand->add_flag("--variants", gallery.variants, "also one tile per D, G, F and diffuse choice (physically based)");
    galleryCommand->add_option("--columns", gallery.columns, "tiles per row (default 3)");
    addFrameOptions(galleryCommand, gallery.frame);

    rejectNonFinite(app);
}

} // namespace specula::cli
