// `specula view`: the window, Dear ImGui and the frame loop. Scripts and --frames make it testable.
#include "ViewCommand.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <utility>

#include "Viewer.h"
#include "ViewerScript.h"
#include "ViewerUi.h"
#include "core/Error.h"
#include "core/ImageIO.h"
#include "core/Log.h"
#include "core/Timer.h"
#include "gl/Debug.h"
#include "gl/State.h"
#include "platform/Context.h"

namespace specula::viewer {

namespace {

/// Dear ImGui for the lifetime of the object (its GLFW and OpenGL 3 backends).
class ImGuiLayer {
public:
    explicit ImGuiLayer(GLFWwindow* window)
    {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr; // no imgui.ini next to the user's files
        ImGui::StyleColorsDark();
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        ImGui_ImplOpenGL3_Init("#version 450 core");
    }
    ~ImGuiLayer()
    {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;
};

} // namespace

int runView(const ViewArgs& args)
{
    if (args.frame.allCameras) throw Error("--camera all is for render (one image per camera); the viewer switches cameras in its Scene panel");
    if (!args.screenshot.empty()) {
        if (args.frames < 1 && args.script.empty()) throw Error("--screenshot needs --frames N (or a script)");
        checkOutputPath(args.screenshot);
    }
    std::optional<ViewerScript> script;
    if (!args.script.empty()) script.emplace(args.script);

    Stopwatch contextClock;
    platform::ContextDesc desc;
    desc.width = args.frame.width.value_or(1280);
    desc.height = args.frame.height.value_or(720);
    desc.title = "Specula";
    auto context = platform::Context::createWindow(desc);
    gl::DebugMonitor debug;
    auto* window = static_cast<GLFWwindow*>(context->nativeWindow());
    const double contextMs = contextClock.elapsedMs();

    Viewer viewer(*context, args.frame);
    viewer.showUi = !args.hideUi;
    viewer.loadScene(args.scene);
    viewer.setContextTime(contextMs);
    viewer.setDebugMonitor(&debug);

    ImGuiLayer imgui(window);
    // After ImGui's backend, which installs its callbacks first and chains to none for drops.
    // Files dropped on the window since the last frame (GLFW calls back during pollEvents);
    // ImGui's GLFW backend keeps its data elsewhere, so the window's user pointer is ours.
    std::vector<std::string> dropped;
    glfwSetWindowUserPointer(window, &dropped);
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
        auto* files = static_cast<std::vector<std::string>*>(glfwGetWindowUserPointer(w));
        for (int i = 0; i < count; ++i) files->emplace_back(paths[i]);
    });

    Stopwatch watchClock;
    auto last = std::chrono::steady_clock::now();
    int framesLeft = script ? script->runUntilFrames(viewer) : 0;
    bool scripted = script.has_value();
    int tailFrames = args.frames;
    const bool interactive = !scripted && args.frames < 1;
    int frameCount = 0;

    while (!context->shouldClose()) {
        context->pollEvents();
        if (interactive && glm::any(glm::lessThanEqual(context->framebufferSize(), glm::ivec2(0)))) {
            context->waitEvents(0.1); // minimised: nothing to draw, no frames to spin through
            continue;
        }
        for (const std::string& path : std::exchange(dropped, {})) viewer.openFile(path);
        if (interactive && watchClock.elapsedMs() > 500.0) {
            // Hot reload: a changed shader file rebuilds the programs; errors show in the UI.
            // Scripts poll with `poll-shaders`, which runs the same check.
            watchClock.reset();
            viewer.reloadChangedShaders();
        }

        const auto now = std::chrono::steady_clock::now();
        const float delta = std::chrono::duration<float>(now - last).count();
        last = now;

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        handleInput(viewer, delta);
        drawUi(viewer);
        ImGui::Render();

        viewer.renderFrame(delta);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        viewer.renderer().invalidateGlState(); // ImGui's backend changed GL state behind the cache
        viewer.captureWindow();
        context->swapBuffers();
        ++frameCount;
        viewer.advanceEnvironmentBake();

        if (debug.errorCount() > 0) break; // reported below
        if (interactive) continue;
        if (scripted) {
            if (--framesLeft > 0) continue;
            framesLeft = script->runUntilFrames(viewer);
            if (framesLeft > 0) continue;
            scripted = false;
        }
        if (tailFrames-- > 1) continue;
        if (!args.screenshot.empty()) viewer.screenshot(args.screenshot);
        break;
    }
    log::info("viewer: {} frames", frameCount);
    if (debug.errorCount() > 0) {
        // GL errors are bugs: a test must not pass over one.
        if (!args.screenshot.empty()) std::filesystem::remove(args.screenshot);
        throw Error("OpenGL reported {} error(s); first: {}", debug.errorCount(), debug.errors().front());
    }
    return 0;
}

} // namespace specula::viewer
