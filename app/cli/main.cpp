// specula: the command line. Thin: parses arguments and calls the library.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "Commands.h"
#include "core/Error.h"
#include "core/Log.h"

using namespace specula;

namespace {

void addFrameOptions(CLI::App* command, cli::FrameOptions& frame)
{
    command->add_option("--width", frame.width, "image width in pixels (default 1280)");
    command->add_option("--height", frame.height, "image height in pixels (default 720)");
    command->add_option("--msaa", frame.msaa, "samples per pixel: 1 (pixel centre, no anti-aliasing), 2, 4 (default), 8");
    command->add_option("--exposure", frame.exposure, "exposure in EV: the image is multiplied by 2^EV (default 0)");
    command->add_option("--tonemap", frame.tonemap, "none, reinhard, reinhard-ext, aces, neutral (default)");
    command->add_option("--brdf-g", frame.brdfG, "masking-shadowing: smith-ggx (glTF, default) or schlick-ggx (UE4)");
    command->add_option("--camera", frame.camera, "index of the scene camera to use (default: the first, else framed)");
    command->add_flag("--no-default-lights", frame.noDefaultLights, "never add the default light rig");
    command->add_option("--env", frame.env, "environment: an equirectangular .hdr or .exr, sky (procedural, the default) or none");
    command->add_option("--env-color", frame.envColor, "a constant environment of radiance R,G,B (cd/m²)");
    command->add_option("--env-intensity", frame.envIntensity, "scales the environment (default 1)");
    command->add_option("--env-rotation", frame.envRotation, "turns the environment about +Y, degrees");
    command->add_option("--skybox", frame.skybox, "on (default), off, or blur=R (R = roughness 0..1)");
    command->add_option("--bake-preset", frame.bakePreset, "default, or reference (the LearnOpenGL tutorial's bake sizes)");
    command->add_flag("--no-cache", frame.noCache, "bake the environment even if the bake cache holds it, and do not cache");
    command->add_flag("--gizmos", frame.gizmos, "draw every light as a disc in the light's colour");
}

} // namespace

int main(int argc, char** argv)
{
    log::init();
    CLI::App app{"Specula: a physically based renderer (OpenGL 4.5)", "specula"};
    app.require_subcommand(1);
    // One line per failure: the first line of CLI11's message plus a pointer to --help.
    app.failure_message([](const CLI::App*, const CLI::Error& e) {
        return std::string("specula: error: ") + e.what() + " (see --help)\n";
    });

    cli::RenderArgs render;
    CLI::App* renderCommand = app.add_subcommand("render", "render a scene to an image (PNG, Radiance HDR or OpenEXR)");
    renderCommand->add_option("scene", render.scene, "a .gltf, .glb or .json scene, or a built-in: demo (default), learnopengl, learnopengl-ibl");
    renderCommand->add_option("-o,--output", render.output, "output image: .png (tone-mapped sRGB), .hdr or .exr (linear radiance x 2^EV)");
    addFrameOptions(renderCommand, render.frame);

    CLI::App* infoCommand = app.add_subcommand("info", "print the OpenGL vendor, renderer, version and limits");

    cli::BenchArgs bench;
    CLI::App* benchCommand = app.add_subcommand("bench", "measure start-up and frame times of built-in scenes");
    benchCommand->add_option("--scene", bench.scenes, "scenes to measure (default: demo learnopengl learnopengl-ibl)");
    benchCommand->add_option("-o,--output", bench.output, "JSON results file (default bench.json)");
    benchCommand->add_option("--frames", bench.frames, "frames to time per scene (default 60)");
    benchCommand->add_option("--warmup", bench.warmup, "untimed frames first (default 5)");
    addFrameOptions(benchCommand, bench.frame);

    cli::BakeArgs bake;
    CLI::App* bakeCommand = app.add_subcommand("bake", "bake an environment for image-based lighting into the cache");
    bakeCommand->add_option("env", bake.env, "an equirectangular .hdr or .exr, or sky")->required();
    bakeCommand->add_option("--bake-preset", bake.preset, "default, or reference (the LearnOpenGL tutorial's bake sizes)");
    bakeCommand->add_option("--cache-dir", bake.cacheDirectory, "where to write (default: $SPECULA_CACHE_DIR, $XDG_CACHE_HOME/specula or ~/.cache/specula)");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }

    try {
        if (*renderCommand) return cli::runRender(render);
        if (*infoCommand) return cli::runInfo();
        if (*benchCommand) return cli::runBench(bench);
        if (*bakeCommand) return cli::runBake(bake);
    } catch (const Error& e) {
        std::fprintf(stderr, "specula: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "specula: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
