#include "Viewer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <utility>

#include "core/Error.h"
#include "scene/DemoScenes.h"
#include "core/ImageIO.h"
#include "core/Log.h"
#include "core/ProcessClock.h"
#include "core/Timer.h"
#include "gl/Debug.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "platform/Context.h"
#include "scene/Picking.h"
#include "scene/Pose.h"
#include "shading/SunExtraction.h"

namespace specula::viewer {

namespace {

std::string lowerExtension(const std::string& path)
{
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

std::vector<render::PlacedLight> currentLights(const render::Renderer& renderer)
{
    std::vector<render::PlacedLight> lights;
    for (int i = 0; i < renderer.lightCount(); ++i) lights.push_back(renderer.light(i));
    return lights;
}

} // namespace

Viewer::Viewer(platform::Context& context, const setup::FrameOptions& options)
    : mContext(context), mOptions(options), mRenderer(std::make_unique<render::Renderer>()), mShaderWatcher(gl::shaderRoot())
{
    mRenderer->setCacheDirectory(setup::cacheDirectory(mOptions));
}

Viewer::~Viewer() = default;

void Viewer::loadScene(const std::string& name)
{
    Stopwatch load;
    const bool first = mSceneName.empty();
    scene::SceneDocument document = setup::loadSceneOrBuiltin(name, mOptions.load, mOptions.lights);
    render::FrameSettings settings = setup::resolveSettings(document, mOptions);
    // The first scene brings its environment (or the command line's), and with --env-sun
    // extract its sun's light; a dropped scene keeps the one on screen, and that light.
    std::optional<render::EnvironmentMap> environment;
    if (first) {
        mExtractSun = setup::extractsSun(document, mOptions);
        environment = setup::loadEnvironment(document, mOptions);
        mSunRotation = settings.environment.rotationDegrees;
        mSunIntensity = settings.environment.intensity;
    } else {
        environment = mEnvironment;
        if (mEnvironment && mEnvironment->sun) {
            const render::PlacedLight sun = setup::environmentSunLight(*mEnvironment->sun, mSunRotation, mSunIntensity);
            scene::addLight(document.scene, sun.light, sun.position, sun.direction);
        }
    }
    int defaultLights = 0;
    setup::prepareView(document, mOptions, settings, &defaultLights, environment.has_value());
    mStartup.sceneLoad = load.elapsedMs();
    log::info("loaded {} in {:.0f} ms: {} meshes, {} triangles, {} lights{}", name.empty() ? "demo" : name, mStartup.sceneLoad,
              document.scene.meshes.size(), document.scene.triangleCount(), document.scene.lights.size(),
              defaultLights ? " (default rig)" : "");

    Stopwatch upload;
    mRenderer->setScene(document.scene);
    if (first) mStartup.sceneUpload = upload.elapsedMs();
    // The first scene starts where --animation and --time say (paused when --time is given); a
    // dropped one at its first animation's start, playing.
    const setup::AnimationChoice animation = first ? setup::resolveAnimation(document.scene, mOptions)
                                                   : setup::resolveAnimation(document.scene, setup::FrameOptions{});
    timeline.animation = animation.index;
    timeline.time = animation.seconds;
    timeline.playing = !(first && mOptions.time);
    mPosed.reset();
    // The first scene is drawn with --variant's materials, a dropped one with its own.
    mVariant = first ? setup::resolveVariant(document.scene, mOptions) : -1;
    mRenderer->setVariant(mVariant);
    if (first) {
        settings.gizmos = true; // the viewer shows where its lights are
        mSettings = settings;
        if (environment) {
            Stopwatch bake;
            setEnvironment(*mRenderer, *environment);
            mStartup.environmentBake = bake.elapsedMs();
            mEnvironmentName = mOptions.env.value_or(document.environment.file.empty() ? "sky" : document.environment.file);
        }
        mEnvironment = std::move(environment);
    }
    mDocument = std::move(document);
    mDefaultMaterial = scene::Material{.name = "default"};
    mSceneName = name.empty() ? "demo" : name;
    selectedLight = mRenderer->lightCount() > 0 ? 0 : -1;
    selectedMaterial = 0;
    mSceneCamera = first && mOptions.camera >= 0 ? mOptions.camera : -1;
    mCamera.frame(mDocument.scene.worldBounds());
}

void Viewer::loadEnvironment(const std::string& file)
{
    render::EnvironmentMap map = file == "sky" ? render::proceduralSky() : render::loadEnvironmentMap(file);
    if (mExtractSun) setup::extractEnvironmentSun(map, mSettings.environment.rotationDegrees, mSettings.environment.intensity);
    Stopwatch bake;
    setEnvironment(*mRenderer, map);
    log::info("environment {} ready in {:.0f} ms", file, bake.elapsedMs());
    mEnvironment = std::move(map);
    mEnvironmentName = file;
    placeEnvironmentSun();
}

void Viewer::setSunExtraction(bool extract)
{
    mExtractSun = extract;
    if (!mEnvironment || extract == mEnvironment->sun.has_value()) return;
    render::EnvironmentMap map = *mEnvironment;
    if (extract) {
        if (!setup::extractEnvironmentSun(map, mSettings.environment.rotationDegrees, mSettings.environment.intensity)) return;
    } else {
        render::restoreSun(map);
        log::info("--env-sun keep: the sun is back in the environment");
    }
    setEnvironment(*mRenderer, map);
    mEnvironment = std::move(map);
    placeEnvironmentSun();
}

void Viewer::placeEnvironmentSun()
{
    std::vector<render::PlacedLight> lights = currentLights(*mRenderer);
    const size_t removed = std::erase_if(lights, [](const render::PlacedLight& l) { return l.light.name == setup::kEnvironmentSunName; });
    mSunRotation = mSettings.environment.rotationDegrees;
    mSunIntensity = mSettings.environment.intensity;
    const bool sun = mEnvironment && mEnvironment->sun;
    if (sun) lights.push_back(setup::environmentSunLight(*mEnvironment->sun, mSunRotation, mSunIntensity));
    if (removed == 0 && !sun) return;
    mRenderer->setLights(lights);
    selectedLight = std::min(selectedLight, int(lights.size()) - 1);
}

void Viewer::followEnvironmentSun()
{
    const render::EnvironmentView& e = mSettings.environment;
    if (!mEnvironment || !mEnvironment->sun || (e.rotationDegrees == mSunRotation && e.intensity == mSunIntensity)) return;
    mSunRotation = e.rotationDegrees;
    mSunIntensity = e.intensity;
    const render::PlacedLight sun = setup::environmentSunLight(*mEnvironment->sun, mSunRotation, mSunIntensity);
    for (int i = 0; i < mRenderer->lightCount(); ++i) {
        render::PlacedLight light = mRenderer->light(i);
        if (light.light.name != setup::kEnvironmentSunName) continue;
        light.direction = sun.direction;
        light.light.intensity = sun.light.intensity;
        editLight(i, light);
    }
}

void Viewer::openFile(const std::string& path)
{
    const std::string extension = lowerExtension(path);
    try {
        if (extension == ".hdr" || extension == ".exr") {
            loadEnvironment(path);
        } else if (extension == ".gltf" || extension == ".glb" || extension == ".json") {
            loadScene(path);
        } else {
            throw Error("cannot open {}: not a .gltf, .glb, .json, .hdr or .exr file", path);
        }
        lastError.clear();
        lastMessage = "opened " + path;
    } catch (const std::exception& e) {
        // The scene and environment on screen stay as they were.
        lastError = e.what();
        log::warn("{}", lastError);
    }
}

float Viewer::animationDuration() const
{
    const auto& animations = mDocument.scene.animations;
    if (timeline.animation < 0 || size_t(timeline.animation) >= animations.size()) return 0.0f;
    return animations[size_t(timeline.animation)].duration();
}

void Viewer::setVariant(int variant)
{
    mVariant = variant;
    mRenderer->setVariant(variant);
}

void Viewer::advanceTimeline(float deltaSeconds)
{
    const float duration = animationDuration();
    if (timeline.playing && duration > 0.0f) {
        timeline.time += deltaSeconds * timeline.speed;
        if (timeline.loop) {
            timeline.time = std::fmod(timeline.time, duration);
            if (timeline.time < 0.0f) timeline.time += duration; // playing backwards
        } else {
            timeline.time = std::clamp(timeline.time, 0.0f, duration);
        }
    }
    const std::pair<int, float> pose{timeline.animation, timeline.time};
    if (mPosed != pose) {
        mRenderer->setPose(pose.first, pose.second);
        mPosed = pose;
    }
}

void Viewer::renderFrame(float deltaSeconds)
{
    const glm::ivec2 size = mContext.framebufferSize();
    if (size.x <= 0 || size.y <= 0) return; // minimised
    advanceTimeline(deltaSeconds);
    followEnvironmentSun();
    mSettings.width = size.x;
    mSettings.height = size.y;
    mSettings.autoExposure.deltaTime = deltaSeconds;
    mSettings.selectedLight = selectedLight;
    const float aspect = float(size.x) / float(size.y);
    render::View view;
    if (mSceneCamera >= 0) {
        // A scene camera follows the animation (its node, and KHR_animation_pointer's properties);
        // without one playing, the rest pose needs no pose built each frame.
        std::optional<scene::Pose> pose;
        if (mPosed && mPosed->first >= 0) pose = scene::poseAt(mDocument.scene, mPosed->first, mPosed->second);
        view = render::cameraView(mDocument.scene, mSceneCamera, aspect, pose ? &*pose : nullptr);
    } else {
        view = mCamera.view(aspect);
    }
    mLastView = view;
    mLastSize = glm::vec2(size);
    // The pass times are for the stats panel: with the panels hidden nobody reads them, and
    // timing waits for the GPU at the end of every frame (on llvmpipe, ~1.5 ms of 40 a frame).
    mRenderer->setGpuTiming(gpuTiming && showUi);
    const int errorsBefore = mDebug ? mDebug->errorCount() : 0;
    // Gizmos are part of the editing overlay: hidden with the panels (H), the window shows
    // the scene as `specula render` draws it.
    Stopwatch frameClock;
    render::FrameSettings frameSettings = mSettings;
    frameSettings.gizmos = mSettings.gizmos && showUi;
    // The tone map draws into the window itself (no 8-bit image copied there: 2-3 ms of a
    // 38 ms frame on llvmpipe, docs/performance.md); a screenshot renders the frame again.
    frameSettings.toWindow = true;
    mLastFrameSettings = frameSettings;
    try {
        mRenderer->render(view, frameSettings);
    } catch (const gl::ShaderError& e) {
        // A program compiled on first use (a pass or shading model turned on after a reload)
        // from a file that does not compile: show it and keep the last frame on screen; turning
        // the setting back, or fixing the file, recovers.
        if (lastError != e.what()) log::warn("frame not rendered: {}", e.what());
        lastError = e.what();
        if (mDebug) mDebug->discardAfter(errorsBefore);
        mRenderer->invalidateGlState();
    }
    mRenderer->present(size.x, size.y);
    mLastRenderMs = frameClock.elapsedMs();
    if (mFirstFrame) {
        mStartup.firstRender = frameClock.elapsedMs();
        mStartup.firstFrame = msSinceProcessStart();
        mFirstFrame = false;
        log::debug("first frame at {:.0f} ms: context {:.0f} ms, scene load {:.0f}, upload {:.0f}, environment {:.0f}, render {:.0f}",
                   mStartup.firstFrame, mStartup.context, mStartup.sceneLoad, mStartup.sceneUpload, mStartup.environmentBake,
                   mStartup.firstRender);
    }
    std::rotate(frameTimes.begin(), frameTimes.begin() + 1, frameTimes.end());
    frameTimes.back() = deltaSeconds * 1000.0f;
}

void Viewer::setEnvironment(render::Renderer& renderer, const render::EnvironmentMap& map)
{
    const render::BakeReport report =
        renderer.setEnvironment(map, setup::resolveBakeSettings(mOptions), setup::cacheDirectory(mOptions), render::BakeMode::Progressive);
    mBake = render::BakeProgress{.pending = report.progressive, .fraction = report.progressive ? 0.0 : 1.0};
}

void Viewer::advanceEnvironmentBake()
{
    // At most 100 ms: a frame that compiled programs (the first) is no measure of the next.
    if (mBake.pending) mBake = mRenderer->advanceEnvironmentBake(std::clamp(mLastRenderMs, 8.0, 100.0));
}

bool Viewer::finishEnvironmentBake()
{
    if (!mBake.pending) return false;
    mBake = mRenderer->advanceEnvironmentBake(std::numeric_limits<double>::infinity());
    return true;
}

void Viewer::screenshot(const std::filesystem::path& path)
{
    // The last frame may show the preview of a bake still under way: the full one, drawn again.
    if (finishEnvironmentBake() || mRenderer->lastFrameInWindow()) {
        // The same frame into the 8-bit image (with automatic exposure, one adaptation step on).
        render::FrameSettings again = mLastFrameSettings;
        again.toWindow = false;
        mRenderer->render(mLastView, again);
    }
    writePng(path, mRenderer->readImage());
    lastMessage = "screenshot: " + std::filesystem::absolute(path).string();
    log::info("{}", lastMessage);
}

void Viewer::captureWindow()
{
    if (mPendingWindowShot.empty()) return;
    const std::filesystem::path path = std::exchange(mPendingWindowShot, {});
    const glm::ivec2 size = mContext.framebufferSize();
    ImageRGBA8 image;
    image.width = size.x;
    image.height = size.y;
    const std::vector<uint8_t> pixels = gl::readDefaultFramebuffer(size.x, size.y);
    mRenderer->invalidateGlState(); // the read binding changed behind the cache
    // GL's first row is the bottom one; files want the top one first. The window has no alpha.
    const size_t row = size_t(size.x) * 4;
    image.pixels.resize(pixels.size());
    for (int y = 0; y < size.y; ++y)
        std::copy_n(pixels.begin() + ptrdiff_t(size_t(size.y - 1 - y) * row), row, image.pixels.begin() + ptrdiff_t(size_t(y) * row));
    for (size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;
    try {
        writePng(path, image);
        lastMessage = "window screenshot: " + std::filesystem::absolute(path).string();
        log::info("{}", lastMessage);
    } catch (const std::exception& e) {
        // Mid-frame, from a key or a script: the UI shows it (a script can expect-no-error).
        lastError = e.what();
        log::warn("{}", lastError);
    }
}

bool Viewer::reloadShaders()
{
    // A fresh renderer compiles every program from the files; the old one keeps running until
    // the new one has compiled all it needs, so a compile error leaves the last good programs.
    const int errorsBefore = mDebug ? mDebug->errorCount() : 0;
    const render::BakeProgress bakeBefore = mBake; // the old renderer's, kept if this fails
    try {
        auto fresh = std::make_unique<render::Renderer>();
        fresh->setCacheDirectory(setup::cacheDirectory(mOptions));
        fresh->setScene(mDocument.scene);
        if (mPosed) fresh->setPose(mPosed->first, mPosed->second);
        fresh->setLights(currentLights(*mRenderer));
        // Every material's edits, from the records the old renderer draws with: the default
        // material's too, and fields plain materials do not hold (the classic ks).
        for (int i = 0; i < mRenderer->materialCount(); ++i) {
            fresh->setMaterialShading(i, mRenderer->materialShading(i));
            fresh->setMaterialBlendMode(i, mRenderer->materialBlendMode(i));
            for (int p = 0; p < render::kMaterialParameterCount; ++p) {
                const auto parameter = render::MaterialParameter(p);
                fresh->setMaterialParameter(i, parameter, mRenderer->materialParameter(i, parameter));
            }
        }
        if (mEnvironment) setEnvironment(*fresh, *mEnvironment);
        fresh->prepare(mSettings);
        mRenderer = std::move(fresh);
        lastError.clear();
        lastMessage = "shaders reloaded";
        log::info("{}", lastMessage);
        return true;
    } catch (const std::exception& e) {
        lastError = e.what();
        log::warn("shader reload failed, keeping the last good programs: {}", lastError);
        mBake = bakeBefore;
        // The driver reports a compile error as a GL error too; any other is a bug and stays.
        if (mDebug && dynamic_cast<const gl::ShaderError*>(&e)) mDebug->discardAfter(errorsBefore);
        mRenderer->invalidateGlState();
        return false;
    }
}

bool Viewer::reloadChangedShaders()
{
    if (!mShaderWatcher.changed()) return false;
    log::info("shader files changed under {}", mShaderWatcher.root().string());
    reloadShaders();
    return true;
}

void Viewer::addLight(scene::Light::Type type)
{
    std::vector<render::PlacedLight> lights = currentLights(*mRenderer);
    render::PlacedLight placed;
    placed.light.type = type;
    placed.light.name = type == scene::Light::Type::Spot ? "spot" : type == scene::Light::Type::Point ? "point" : "sun";
    // Halfway to the camera, up and to the right, towards what the camera looks at: the new
    // light and its gizmo are in view at once.
    const glm::vec3 target = mCamera.target();
    const glm::vec3 toEye = mCamera.eye() - target;
    const glm::vec3 right = glm::normalize(glm::cross(-toEye, glm::vec3(0, 1, 0)));
    placed.position = target + 0.5f * toEye + 0.12f * mCamera.distance() * (right + glm::vec3(0, 1, 0));
    placed.direction = glm::normalize(target - placed.position);
    const float distance = glm::length(target - placed.position);
    // About 10 lux at the target: a few times the irradiance of the environments the assets
    // ship with, so that a new light shows clearly.
    placed.light.intensity = type == scene::Light::Type::Directional ? 10.0f : 10.0f * distance * distance;
    placed.light.innerConeAngle = glm::radians(15.0f);
    placed.light.outerConeAngle = glm::radians(25.0f);
    lights.push_back(placed);
    mRenderer->setLights(lights);
    selectedLight = int(lights.size()) - 1;
}

void Viewer::scatterLights(int count)
{
    if (count < 0 || count > (1 << 22)) throw Error("scatter-lights wants 0 to 4194304 lights (got {})", count);
    std::vector<render::PlacedLight> lights = currentLights(*mRenderer);
    const glm::vec3 target = mCamera.target();
    const float side = 2.0f * mCamera.distance();
    const uint32_t first = uint32_t(lights.size());
    for (int i = 0; i < count; ++i) {
        const scene::ScatteredLight s = scene::scatteredLight(first + uint32_t(i), target, side);
        render::PlacedLight placed;
        placed.light = s.light;
        placed.light.name = "scattered";
        placed.position = s.position;
        placed.direction = {0.0f, -1.0f, 0.0f};
        lights.push_back(placed);
    }
    mRenderer->setLights(lights);
}

void Viewer::removeLight(int index)
{
    std::vector<render::PlacedLight> lights = currentLights(*mRenderer);
    if (index < 0 || index >= int(lights.size())) throw Error("no light {} (there are {})", index, lights.size());
    lights.erase(lights.begin() + index);
    mRenderer->setLights(lights);
    selectedLight = std::min(selectedLight, int(lights.size()) - 1);
}

void Viewer::editLight(int index, const render::PlacedLight& light)
{
    if (index < 0 || index >= mRenderer->lightCount()) throw Error("no light {} (there are {})", index, mRenderer->lightCount());
    const render::LightWrite w = mRenderer->setLight(index, light);
    mLastLightUpload = {index, w.offset, w.size, w.bytes, w.lightOffset, w.lightSize};
    log::debug("light {}: uploaded {} bytes at offset {}", index, w.bytes, w.offset);
}

scene::Material& Viewer::material(int index)
{
    if (index < 0 || index >= mRenderer->materialCount())
        throw Error("no material {} (there are {})", index, mRenderer->materialCount());
    std::vector<scene::Material>& materials = mDocument.scene.materials;
    return index < int(materials.size()) ? materials[size_t(index)] : mDefaultMaterial;
}

void Viewer::setMaterialModel(int index, scene::ShadingModel model)
{
    material(index); // checks the index
    scene::MaterialShading shading = mRenderer->materialShading(index);
    shading.model = model;
    setMaterialShading(index, shading);
}

void Viewer::setMaterialShading(int index, const scene::MaterialShading& shading)
{
    scene::Material& m = material(index);
    mRenderer->setMaterialShading(index, shading);
    m.shading = shading;
}

void Viewer::setMaterialBlendMode(int index, scene::BlendMode mode)
{
    scene::Material& m = material(index);
    mRenderer->setMaterialBlendMode(index, mode);
    if (m.alphaMode == scene::AlphaMode::Blend) m.blendMode = mode;
}

void Viewer::setMaterialParameter(int index, render::MaterialParameter parameter, const glm::vec4& value)
{
    scene::Material& m = material(index);
    mRenderer->setMaterialParameter(index, parameter, value);
    // The plain copy in step, for the panel and for setMaterialIor.
    switch (parameter) {
    case render::MaterialParameter::BaseColor: m.baseColorFactor = value; break;
    case render::MaterialParameter::Emissive: m.emissiveFactor = glm::vec3(value); m.emissiveStrength = 1.0f; break;
    case render::MaterialParameter::Metallic: m.metallicFactor = value.x; break;
    case render::MaterialParameter::Roughness: m.roughnessFactor = value.x; break;
    case render::MaterialParameter::Shininess: m.shininess = value.x; break;
    case render::MaterialParameter::SpecularFactor: m.specularFactor = value.x; break;
    case render::MaterialParameter::SectorLight: m.sectorLight = int(std::lround(std::clamp(value.x, 0.0f, 255.0f))); break;
    case render::MaterialParameter::ClearcoatFactor: m.clearcoatFactor = std::clamp(value.x, 0.0f, 1.0f); break;
    case render::MaterialParameter::ClearcoatRoughness: m.clearcoatRoughnessFactor = std::clamp(value.x, 0.0f, 1.0f); break;
    case render::MaterialParameter::Dispersion: m.dispersion = std::max(value.x, 0.0f); break;
    case render::MaterialParameter::SheenColor: m.sheenColorFactor = glm::clamp(glm::vec3(value), 0.0f, 1.0f); break;
    case render::MaterialParameter::SheenRoughness: m.sheenRoughnessFactor = std::clamp(value.x, 0.0f, 1.0f); break;
    case render::MaterialParameter::AnisotropyStrength: m.anisotropyStrength = std::clamp(value.x, 0.0f, 1.0f); break;
    case render::MaterialParameter::AnisotropyRotation: m.anisotropyRotation = value.x; break;
    case render::MaterialParameter::IridescenceFactor: m.iridescenceFactor = std::clamp(value.x, 0.0f, 1.0f); break;
    case render::MaterialParameter::IridescenceIor: m.iridescenceIor = std::max(value.x, 1.0f); break;
    case render::MaterialParameter::IridescenceThickness:
        m.iridescenceThicknessMinimum = std::max(value.x, 0.0f);
        m.iridescenceThicknessMaximum = std::max(value.y, 0.0f);
        break;
    case render::MaterialParameter::DiffuseTransmission: m.diffuseTransmissionFactor = std::clamp(value.x, 0.0f, 1.0f); break;
    case render::MaterialParameter::DiffuseTransmissionColor:
        m.diffuseTransmissionColorFactor = glm::clamp(glm::vec3(value), 0.0f, 1.0f);
        break;
    case render::MaterialParameter::PhongSpecular: // the classic ks: only in the record
    case render::MaterialParameter::SpecularColor: break; // colour × ior: setMaterialIor
    }
}

void Viewer::setMaterialIor(int index, float ior)
{
    // Below 1 F0 would grow again; 1 is no reflection at all.
    if (!(ior >= 1.0f)) throw Error("an index of refraction is at least 1 (got {})", ior);
    scene::Material& m = material(index);
    m.ior = ior;
    setMaterialParameter(index, render::MaterialParameter::SpecularColor,
                         glm::vec4(m.specularColorFactor * (scene::f0FromIor(ior) / 0.04f), 0.0f));
}

int Viewer::pickMaterial(float x, float y)
{
    // The pixel's centre back through the last frame's camera: NDC at the near and far planes.
    const glm::vec2 ndc(2.0f * (x + 0.5f) / mLastSize.x - 1.0f, 1.0f - 2.0f * (y + 0.5f) / mLastSize.y);
    const glm::mat4 inverse = glm::inverse(mLastView.projection * mLastView.view);
    const glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f);
    const glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 origin = glm::vec3(nearPoint) / nearPoint.w;
    const glm::vec3 direction = glm::vec3(farPoint) / farPoint.w - origin;
    const auto hit = scene::pick(mDocument.scene, origin, direction);
    if (!hit) return -1;
    // What the primitive draws with under the chosen variant; the renderer's registry puts the
    // glTF default material after the scene's.
    int material = hit->material;
    for (const scene::VariantMapping& mapping : mDocument.scene.meshes[size_t(hit->mesh)].primitives[size_t(hit->primitive)].variants)
        if (mapping.variant == mVariant) material = mapping.material;
    selectedMaterial = material >= 0 ? material : int(mDocument.scene.materials.size());
    lastMessage = "picked material " + std::to_string(selectedMaterial);
    panelRequests["Materials"] = true;
    log::info("{} (node {}, mesh {})", lastMessage, hit->node, hit->mesh);
    return selectedMaterial;
}

void Viewer::useCamera(int index)
{
    if (index >= int(mDocument.scene.cameraInstances().size()))
        throw Error("no camera {} (the scene has {})", index, mDocument.scene.cameraInstances().size());
    mSceneCamera = std::max(index, -1);
}

void Viewer::resetCamera()
{
    mSceneCamera = -1;
    mCamera.frame(mDocument.scene.worldBounds());
}

} // namespace specula::viewer
