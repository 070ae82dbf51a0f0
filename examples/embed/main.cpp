// Renders a glTF model under an environment, headless, to a PNG, with Specula as a library.
//   specula_embed MODEL.gltf|.glb OUT.png [ENV.hdr|.exr]   (no ENV: the procedural sky)
#include <specula/Specula.h>

#include <cstdio>

int main(int argc, char** argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s MODEL.glb OUT.png [ENV.hdr]\n", argv[0]);
        return 2;
    }
    using namespace specula;
    try {
        // A GL 4.5 context with no window: EGL, on Mesa's llvmpipe without a GPU.
        const auto context = platform::Context::createHeadless();

        const scene::Scene model = scene::loadGltf(argv[1]);
        render::Renderer renderer;
        renderer.setScene(model);
        renderer.setEnvironment(argc > 3 ? render::loadEnvironmentMap(argv[3]) : render::proceduralSky());

        render::FrameSettings settings;
        settings.width = 320;
        settings.height = 240;
        settings.exposureEv = 0.0f;
        settings.tonemap = render::Tonemap::Neutral;
        settings.bloom.enabled = true;
        const float aspect = float(settings.width) / float(settings.height);
        const render::View view = render::defaultView(model, -1, aspect); // its camera, or framed

        renderer.render(view, settings);
        writePng(argv[2], renderer.readImage());
        std::printf("Specula %s: wrote %s (%dx%d)\n", versionString(), argv[2], settings.width, settings.height);
        return 0;
    } catch (const Error& e) {
        std::fprintf(stderr, "specula_embed: %s\n", e.what());
        return 1;
    }
}
