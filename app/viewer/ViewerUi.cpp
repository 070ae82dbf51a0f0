#include "ViewerUi.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "Viewer.h"
#include "core/Error.h"
#include "scene/Scene.h"
#include "shading/BrdfPlot.h"
#include "shading/ShadingVariant.h"
#include "settings/PassSettings.h"

namespace specula::viewer {

namespace {

std::string timestampedScreenshotName()
{
    const std::time_t now = std::time(nullptr);
    char name[64];
    std::strftime(name, sizeof(name), "specula-%Y%m%d-%H%M%S.png", std::localtime(&now));
    return name;
}

void takeScreenshot(Viewer& viewer)
{
    try {
        viewer.screenshot(timestampedScreenshotName());
    } catch (const std::exception& e) {
        viewer.lastError = e.what();
    }
}

/// Runs an action that may throw on bad input; the message goes to the UI.
template <typename Action>
void guarded(Viewer& viewer, Action&& action)
{
    try {
        action();
    } catch (const std::exception& e) {
        viewer.lastError = e.what();
    }
}

/// A panel's collapsing header, opened or closed first if a pick or a script asked.
bool panelHeader(Viewer& viewer, const char* name, ImGuiTreeNodeFlags flags = 0)
{
    if (const auto request = viewer.panelRequests.find(name); request != viewer.panelRequests.end()) {
        ImGui::SetNextItemOpen(request->second);
        viewer.panelRequests.erase(request);
    }
    return ImGui::CollapsingHeader(name, flags);
}

void drawNode(const scene::Scene& scene, int index)
{
    const scene::Node& node = scene.nodes[size_t(index)];
    const std::string label = (node.name.empty() ? "node " + std::to_string(index) : node.name) +
                              (node.mesh >= 0 ? "  [mesh]" : "") + (node.camera >= 0 ? "  [camera]" : "") +
                              (node.light >= 0 ? "  [light]" : "");
    const ImGuiTreeNodeFlags flags = node.children.empty() ? ImGuiTreeNodeFlags_Leaf : 0;
    if (ImGui::TreeNodeEx(reinterpret_cast<void*>(intptr_t(index)), flags, "%s", label.c_str())) {
        for (int child : node.children) drawNode(scene, child);
        ImGui::TreePop();
    }
}

void statisticsPanel(Viewer& viewer)
{
    if (!panelHeader(viewer, "Statistics", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::Text("%.1f FPS (%.2f ms)", io.Framerate, 1000.0f / std::max(io.Framerate, 1e-3f));
    ImGui::PlotLines("frame ms", viewer.frameTimes.data(), int(viewer.frameTimes.size()), 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 50));
    const render::FrameStats& stats = viewer.renderer().stats();
    ImGui::Text("%d draw calls, %zu triangles", stats.drawCalls, stats.triangles);
    if (stats.clusters.slices > 0) {
        const auto& c = stats.clusters;
        ImGui::Text("light clusters %dx%dx%d: %d lights in view, %d directional", c.tilesX, c.tilesY, c.slices, c.lightsInView,
                    c.directional);
        ImGui::Text("  per cluster: max %d, mean %.2f (%zu entries)", c.maxPerCluster, c.meanPerCluster, c.entries);
        for (const render::PassTiming& pass : stats.passes)
            if (std::string_view(pass.name) == "light culling") ImGui::Text("  culling %.3f ms (GPU timing)", pass.gpuMs);
    }
    if (stats.shadows.lights > 0 || stats.shadows.dropped > 0)
        ImGui::Text("shadows: %d lights, %d views (%d drawn, %d kept), %d left out", stats.shadows.lights, stats.shadows.views,
                    stats.shadows.rendered, stats.shadows.cached, stats.shadows.dropped);
    ImGui::Checkbox("GPU timing per pass", &viewer.gpuTiming);
    double total = 0.0;
    for (const render::PassTiming& pass : stats.passes) {
        ImGui::Text("  %-16s %7.3f ms", pass.name, pass.gpuMs);
        total += pass.gpuMs;
    }
    if (!stats.passes.empty()) ImGui::Text("  %-16s %7.3f ms", "total", total);
    const StartupTimes& s = viewer.startup();
    ImGui::Text("start-up: context %.0f ms, scene load %.0f ms, upload %.0f ms,", s.context, s.sceneLoad, s.sceneUpload);
    ImGui::Text("  environment bake %.0f ms, first render %.0f ms,", s.environmentBake, s.firstRender);
    ImGui::Text("  first frame at %.0f ms", s.firstFrame);
    if (viewer.bakeProgress().pending)
        ImGui::Text("environment: a preview while the full bake runs (%.0f %%)", 100.0 * viewer.bakeProgress().fraction);
}

void scenePanel(Viewer& viewer)
{
    if (!panelHeader(viewer, "Scene")) return;
    const scene::Scene& scene = viewer.document().scene;
    ImGui::Text("%s: %zu meshes, %zu materials, %zu triangles", viewer.sceneName().c_str(), scene.meshes.size(),
                scene.materials.size(), scene.triangleCount());
    const scene::Bounds bounds = scene.worldBounds();
    if (!bounds.empty())
        ImGui::Text("bounds (%.2f %.2f %.2f) to (%.2f %.2f %.2f)", bounds.min.x, bounds.min.y, bounds.min.z, bounds.max.x,
                    bounds.max.y, bounds.max.z);
    const auto cameras = scene.cameraInstances();
    if (ImGui::RadioButton("orbit camera", viewer.sceneCamera() < 0)) viewer.useCamera(-1);
    for (size_t i = 0; i < cameras.size(); ++i) {
        const std::string& name = scene.cameras[size_t(cameras[i].camera)].name;
        const std::string label = "camera " + std::to_string(i) + (name.empty() ? "" : ": " + name);
        if (ImGui::RadioButton(label.c_str(), viewer.sceneCamera() == int(i))) viewer.useCamera(int(i));
    }
    ImGui::Checkbox("fly camera (C; WASD, Q/E, drag to look)", &viewer.flyMode);
    if (ImGui::TreeNode("nodes")) {
        for (int root : scene.roots) drawNode(scene, root);
        ImGui::TreePop();
    }
}

/// The timeline: which animation, play and pause, scrub, speed, loop.
void animationPanel(Viewer& viewer)
{
    const auto& animations = viewer.document().scene.animations;
    if (animations.empty() || !panelHeader(viewer, "Animation", ImGuiTreeNodeFlags_DefaultOpen)) return;
    Timeline& t = viewer.timeline;
    auto label = [&](int index) {
        if (index < 0) return std::string("none (rest pose)");
        const std::string& name = animations[size_t(index)].name;
        return std::to_string(index) + ": " + (name.empty() ? "unnamed" : name);
    };
    if (ImGui::BeginCombo("animation", label(t.animation).c_str())) {
        for (int i = -1; i < int(animations.size()); ++i)
            if (ImGui::Selectable(label(i).c_str(), i == t.animation)) {
                t.animation = i;
                t.time = 0.0f;
            }
        ImGui::EndCombo();
    }
    if (ImGui::Button(t.playing ? "pause" : "play")) t.playing = !t.playing;
    ImGui::SameLine();
    if (ImGui::Button("|<")) t.time = 0.0f;
    ImGui::SameLine();
    ImGui::Checkbox("loop", &t.loop);
    const float duration = viewer.animationDuration();
    ImGui::SliderFloat("time (s)", &t.time, 0.0f, std::max(duration, 1e-3f), "%.3f");
    ImGui::SliderFloat("speed", &t.speed, -2.0f, 4.0f, "%.2fx");
    ImGui::TextDisabled("%.3f s long", duration);
}

void lightsPanel(Viewer& viewer)
{
    if (!panelHeader(viewer, "Lights", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const render::Renderer& renderer = viewer.renderer();
    if (ImGui::Button("+ point")) guarded(viewer, [&] { viewer.addLight(scene::Light::Type::Point); });
    ImGui::SameLine();
    if (ImGui::Button("+ spot")) guarded(viewer, [&] { viewer.addLight(scene::Light::Type::Spot); });
    ImGui::SameLine();
    if (ImGui::Button("+ directional")) guarded(viewer, [&] { viewer.addLight(scene::Light::Type::Directional); });
    ImGui::Checkbox("gizmos", &viewer.settings().gizmos);
    static int scatter = 1024;
    ImGui::SetNextItemWidth(100.0f);
    ImGui::InputInt("##scatter", &scatter, 256, 4096);
    ImGui::SameLine();
    if (ImGui::Button("scatter lights")) guarded(viewer, [&] { viewer.scatterLights(std::max(scatter, 0)); });
    static constexpr const char* kTypes[] = {"directional", "point", "spot"};
    // Thousands of lights: the first 256 are listed (each a tree node), the rest counted.
    constexpr int kListed = 256;
    if (renderer.lightCount() > kListed) ImGui::Text("%d lights; the first %d:", renderer.lightCount(), kListed);
    for (int i = 0; i < std::min(renderer.lightCount(), kListed); ++i) {
        const render::PlacedLight& l = renderer.light(i);
        const std::string label = std::to_string(i) + ": " + (l.light.name.empty() ? "light" : l.light.name) + " (" +
                                  kTypes[int(l.light.type)] + ")";
        if (ImGui::Selectable(label.c_str(), viewer.selectedLight == i)) viewer.selectedLight = i;
    }
    const int i = viewer.selectedLight;
    if (i < 0 || i >= renderer.lightCount()) return;
    render::PlacedLight l = renderer.light(i);
    bool changed = false;
    ImGui::Separator();
    changed |= ImGui::ColorEdit3("colour", &l.light.color.x);
    changed |= ImGui::DragFloat(l.light.type == scene::Light::Type::Directional ? "intensity (lux)" : "intensity (cd)",
                                &l.light.intensity, 0.05f * std::max(l.light.intensity, 1.0f), 0.0f, 1e6f, "%.3f");
    if (l.light.type != scene::Light::Type::Directional) {
        changed |= ImGui::DragFloat3("position", &l.position.x, 0.01f);
        changed |= ImGui::DragFloat("range (0 = none)", &l.light.range, 0.05f, 0.0f, 1e4f);
    }
    if (l.light.type != scene::Light::Type::Point) changed |= ImGui::DragFloat3("direction", &l.direction.x, 0.01f, -1.0f, 1.0f);
    if (l.light.type == scene::Light::Type::Spot) {
        float inner = glm::degrees(l.light.innerConeAngle), outer = glm::degrees(l.light.outerConeAngle);
        if (ImGui::SliderFloat("inner cone", &inner, 0.0f, outer, "%.1f deg")) {
            l.light.innerConeAngle = glm::radians(inner);
            changed = true;
        }
        if (ImGui::SliderFloat("outer cone", &outer, inner, 90.0f, "%.1f deg")) {
            l.light.outerConeAngle = glm::radians(outer);
            changed = true;
        }
    }
    changed |= ImGui::Checkbox("casts shadows", &l.light.castShadows);
    if (l.light.type == scene::Light::Type::Directional) {
        float diameter = glm::degrees(l.light.angularDiameter);
        if (ImGui::SliderFloat("angular diameter", &diameter, 0.0f, 10.0f, "%.2f deg")) {
            l.light.angularDiameter = glm::radians(diameter);
            changed = true;
        }
    } else {
        changed |= ImGui::SliderFloat("radius (soft shadows)", &l.light.radius, 0.0f, 2.0f, "%.3f m");
    }
    if (changed) guarded(viewer, [&] { viewer.editLight(i, l); });
    const LightUpload& u = viewer.lastLightUpload();
    if (u.light >= 0)
        ImGui::TextDisabled("last edit: light %d, %zu bytes at offset %zu%s", u.light, u.bytes, u.offset,
                            u.onlyThatLight() ? " (only its bytes)" : "");
    if (ImGui::Button("remove")) guarded(viewer, [&] { viewer.removeLight(i); });
}

/// A combo over an optional enum: "frame default" (unset) or one of `count` values.
template <typename Enum>
bool termCombo(const char* label, std::optional<Enum>& value, int count, const char* (*name)(Enum))
{
    bool changed = false;
    if (ImGui::BeginCombo(label, value ? name(*value) : "frame default")) {
        if (ImGui::Selectable("frame default", !value)) {
            value.reset();
            changed = true;
        }
        for (int k = 0; k < count; ++k) {
            if (ImGui::Selectable(name(Enum(k)), value == Enum(k))) {
                value = Enum(k);
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

void materialsPanel(Viewer& viewer)
{
    if (!panelHeader(viewer, "Materials")) return;
    ImGui::TextDisabled("click on an object to pick its material");
    render::Renderer& renderer = viewer.renderer();
    std::vector<scene::Material>& materials = viewer.document().scene.materials;
    const int count = renderer.materialCount();
    if (count == 0) return;
    // KHR_materials_variants: the whole scene's choice of materials.
    const std::vector<std::string>& variants = viewer.document().scene.variants;
    if (!variants.empty()) {
        auto variantName = [&](int i) { return i < 0 ? std::string("none (the file's materials)") : std::to_string(i) + ": " + variants[size_t(i)]; };
        if (ImGui::BeginCombo("variant", variantName(viewer.variant()).c_str())) {
            for (int i = -1; i < int(variants.size()); ++i)
                if (ImGui::Selectable(variantName(i).c_str(), i == viewer.variant())) viewer.setVariant(i);
            ImGui::EndCombo();
        }
    }
    int& m = viewer.selectedMaterial;
    m = std::clamp(m, 0, count - 1);
    auto nameOf = [&](int i) {
        return i < int(materials.size()) ? std::to_string(i) + ": " + materials[size_t(i)].name : std::to_string(i) + ": default";
    };
    if (ImGui::BeginCombo("material", nameOf(m).c_str())) {
        for (int i = 0; i < count; ++i)
            if (ImGui::Selectable(nameOf(i).c_str(), i == m)) m = i;
        ImGui::EndCombo();
    }
    const scene::MaterialShading shading = renderer.materialShading(m);
    const scene::ShadingModel model = shading.model.value_or(scene::ShadingModel::Pbr);
    if (ImGui::BeginCombo("shading model", scene::shadingModelName(model))) {
        for (int k = 0; k < scene::kShadingModelCount; ++k) {
            const auto candidate = scene::ShadingModel(k);
            if (ImGui::Selectable(scene::shadingModelName(candidate), candidate == model))
                guarded(viewer, [&] { viewer.setMaterialModel(m, candidate); });
        }
        ImGui::EndCombo();
    }
    if (model == scene::ShadingModel::Unlit)
        ImGui::TextWrapped("unlit (glTF KHR_materials_unlit): shows base colour x texture x vertex colour%s; lights, "
                           "the environment and the BRDF below do not apply",
                           viewer.material(m).emissiveTexture.valid() || viewer.material(m).emissiveFactor != glm::vec3(0.0f)
                               ? " + emission" : "");
    // The BRDF terms of the physically based model; unset = the frame's choice.
    scene::MaterialShading terms = shading;
    bool termsChanged = false;
    termsChanged |= termCombo("D (distribution)", terms.distribution, 3, scene::brdfDistributionName);
    termsChanged |= termCombo("G (masking)", terms.geometry, 7, scene::brdfGeometryName);
    termsChanged |= termCombo("F (Fresnel)", terms.fresnel, 3, scene::brdfFresnelName);
    termsChanged |= termCombo("diffuse", terms.diffuse, 3, scene::brdfDiffuseName);
    if (termsChanged) guarded(viewer, [&] { viewer.setMaterialShading(m, terms); });
    // What a blended material's alpha scales (docs/transparency.md).
    if (viewer.material(m).alphaMode == scene::AlphaMode::Blend) {
        const scene::BlendMode mode = renderer.materialBlendMode(m);
        auto name = [](scene::BlendMode b) { return b == scene::BlendMode::Transparent ? "transparent (highlights kept)" : "fade"; };
        if (ImGui::BeginCombo("blend mode", name(mode))) {
            for (auto b : {scene::BlendMode::Fade, scene::BlendMode::Transparent})
                if (ImGui::Selectable(name(b), b == mode)) guarded(viewer, [&] { viewer.setMaterialBlendMode(m, b); });
            ImGui::EndCombo();
        }
    }
    // Thumbnails, drawn by ImGui's backend straight from the renderer's textures (sRGB ones
    // show a little dark: the UI does not encode).
    // Every texture the material samples, in scene::kMaterialTextures' order, five to a row.
    static constexpr const char* kSlots[] = {"base colour", "metal/rough", "normal", "occlusion", "emissive",
                                             "clearcoat", "coat rough", "coat normal", "sheen colour", "sheen rough",
                                             "anisotropy", "iridescence", "film thick", "specular", "spec colour",
                                             "transmission", "thickness", "diffuse trans", "d-trans colour"};
    static_assert(std::size(kSlots) == scene::kMaterialTextures.size());
    const std::vector<uint32_t> textures = renderer.materialTextureNames(m);
    int shown = 0;
    for (size_t k = 0; k < textures.size() && k < std::size(kSlots); ++k) {
        if (!textures[k]) continue;
        if (shown++ % 5 != 0) ImGui::SameLine();
        ImGui::BeginGroup();
        ImGui::Image(reinterpret_cast<ImTextureID>(uintptr_t(textures[k])), ImVec2(64, 64));
        ImGui::TextDisabled("%s", kSlots[k]);
        ImGui::EndGroup();
    }
    // Parameters as the renderer's record holds them (the default material's too); each edit
    // rewrites that field's bytes only (Renderer::setMaterialParameter).
    using render::MaterialParameter;
    auto value = [&](MaterialParameter p) { return renderer.materialParameter(m, p); };
    auto set = [&](MaterialParameter p, const glm::vec4& v) { guarded(viewer, [&] { viewer.setMaterialParameter(m, p, v); }); };
    glm::vec4 color = value(MaterialParameter::BaseColor);
    if (ImGui::ColorEdit4("base colour", &color.x)) set(MaterialParameter::BaseColor, color);
    float metallic = value(MaterialParameter::Metallic).x, roughness = value(MaterialParameter::Roughness).x;
    if (ImGui::SliderFloat("metallic", &metallic, 0.0f, 1.0f)) set(MaterialParameter::Metallic, glm::vec4(metallic));
    if (ImGui::SliderFloat("roughness", &roughness, 0.0f, 1.0f)) set(MaterialParameter::Roughness, glm::vec4(roughness));
    glm::vec3 emissive = glm::vec3(value(MaterialParameter::Emissive));
    if (ImGui::DragFloat3("emissive (cd/m2)", &emissive.x, 0.01f, 0.0f, 1e5f)) set(MaterialParameter::Emissive, glm::vec4(emissive, 0.0f));
    {
        const scene::Material& plain = viewer.material(m);
        float ior = plain.ior.value_or(1.5f);
        if (ImGui::DragFloat("IOR", &ior, 0.005f, 1.0f, 4.0f, plain.ior ? "%.3f" : "%.3f (unset: F0 0.04)"))
            guarded(viewer, [&] { viewer.setMaterialIor(m, std::max(ior, 1.0f)); });
        const float f0 = 0.04f * value(MaterialParameter::SpecularColor).y * value(MaterialParameter::SpecularFactor).x;
        ImGui::SameLine();
        ImGui::TextDisabled("F0 %.3f", f0);
    }
    ImGui::Separator();
    ImGui::TextDisabled("KHR_materials_clearcoat");
    float clearcoat = value(MaterialParameter::ClearcoatFactor).x, clearcoatRoughness = value(MaterialParameter::ClearcoatRoughness).x;
    if (ImGui::SliderFloat("clearcoat", &clearcoat, 0.0f, 1.0f)) set(MaterialParameter::ClearcoatFactor, glm::vec4(clearcoat));
    if (ImGui::SliderFloat("clearcoat roughness", &clearcoatRoughness, 0.0f, 1.0f))
        set(MaterialParameter::ClearcoatRoughness, glm::vec4(clearcoatRoughness));
    ImGui::Separator();
    ImGui::TextDisabled("KHR_materials_dispersion (volumes)");
    float dispersion = value(MaterialParameter::Dispersion).x;
    if (ImGui::SliderFloat("dispersion (20/V)", &dispersion, 0.0f, 20.0f)) set(MaterialParameter::Dispersion, glm::vec4(dispersion));
    ImGui::TextDisabled("KHR_materials_sheen");
    glm::vec4 sheenColor = value(MaterialParameter::SheenColor);
    if (ImGui::ColorEdit3("sheen colour", &sheenColor.x)) set(MaterialParameter::SheenColor, sheenColor);
    float sheenRoughness = value(MaterialParameter::SheenRoughness).x;
    if (ImGui::SliderFloat("sheen roughness", &sheenRoughness, 0.0f, 1.0f)) set(MaterialParameter::SheenRoughness, glm::vec4(sheenRoughness));
    ImGui::TextDisabled("KHR_materials_anisotropy (GGX)");
    float anisotropy = value(MaterialParameter::AnisotropyStrength).x, rotation = value(MaterialParameter::AnisotropyRotation).x;
    if (ImGui::SliderFloat("anisotropy", &anisotropy, 0.0f, 1.0f)) set(MaterialParameter::AnisotropyStrength, glm::vec4(anisotropy));
    if (ImGui::SliderAngle("anisotropy rotation", &rotation, -180.0f, 180.0f)) set(MaterialParameter::AnisotropyRotation, glm::vec4(rotation));
    ImGui::TextDisabled("KHR_materials_iridescence");
    float iridescence = value(MaterialParameter::IridescenceFactor).x, iridescenceIor = value(MaterialParameter::IridescenceIor).x;
    glm::vec4 thickness = value(MaterialParameter::IridescenceThickness);
    if (ImGui::SliderFloat("iridescence", &iridescence, 0.0f, 1.0f)) set(MaterialParameter::IridescenceFactor, glm::vec4(iridescence));
    if (ImGui::SliderFloat("film IOR", &iridescenceIor, 1.0f, 3.0f)) set(MaterialParameter::IridescenceIor, glm::vec4(iridescenceIor));
    if (ImGui::DragFloat2("film thickness min, max (nm)", &thickness.x, 1.0f, 0.0f, 2000.0f))
        set(MaterialParameter::IridescenceThickness, thickness);
    ImGui::TextDisabled("KHR_materials_diffuse_transmission");
    float diffuseTransmission = value(MaterialParameter::DiffuseTransmission).x;
    if (ImGui::SliderFloat("diffuse transmission", &diffuseTransmission, 0.0f, 1.0f))
        set(MaterialParameter::DiffuseTransmission, glm::vec4(diffuseTransmission));
    glm::vec4 transmittedColor = value(MaterialParameter::DiffuseTransmissionColor);
    if (ImGui::ColorEdit3("transmitted colour", &transmittedColor.x)) set(MaterialParameter::DiffuseTransmissionColor, transmittedColor);
    ImGui::Separator();
    ImGui::TextDisabled("Phong, Blinn-Phong, Gouraud, flat");
    glm::vec4 ks = value(MaterialParameter::PhongSpecular);
    if (ImGui::ColorEdit3("specular ks", &ks.x)) set(MaterialParameter::PhongSpecular, ks);
    float shininess = value(MaterialParameter::Shininess).x;
    if (ImGui::DragFloat("shininess (0: auto)", &shininess, 0.5f, 0.0f, 1e4f)) set(MaterialParameter::Shininess, glm::vec4(shininess));
    ImGui::Separator();
    ImGui::TextDisabled("Doom");
    int sector = int(std::lround(value(MaterialParameter::SectorLight).x));
    if (ImGui::SliderInt("sector light", &sector, 0, 255)) set(MaterialParameter::SectorLight, glm::vec4(float(sector)));
}

void brdfPanel(Viewer& viewer)
{
    if (!panelHeader(viewer, "BRDF explorer")) return;
    render::Renderer& renderer = viewer.renderer();
    const int m = viewer.selectedMaterial;
    if (m < 0 || m >= renderer.materialCount()) return;
    float& viewDegrees = viewer.brdfViewDegrees;
    ImGui::SliderFloat("view angle", &viewDegrees, 0.0f, 89.0f, "%.0f deg");
    // The selected material's factors as the shader reads them, and its shading resolved as a
    // draw resolves it (the frame's override, the material's choice, the frame's defaults).
    using render::MaterialParameter;
    auto value = [&](MaterialParameter p) { return renderer.materialParameter(m, p); };
    render::BrdfPlotMaterial material;
    material.baseColor = glm::dvec3(glm::vec3(value(MaterialParameter::BaseColor)));
    material.metallic = value(MaterialParameter::Metallic).x;
    material.perceptualRoughness = value(MaterialParameter::Roughness).x;
    material.specularColor = glm::dvec3(glm::vec3(value(MaterialParameter::SpecularColor)));
    material.specularFactor = value(MaterialParameter::SpecularFactor).x;
    material.phongSpecular = glm::dvec3(glm::vec3(value(MaterialParameter::PhongSpecular)));
    material.shininess = value(MaterialParameter::Shininess).x;
    if (renderer.materialParameter(m, MaterialParameter::ClearcoatFactor).x > 0.0f) {
        material.clearcoat = value(MaterialParameter::ClearcoatFactor).x;
        material.clearcoatRoughness = value(MaterialParameter::ClearcoatRoughness).x;
    }
    material.sheenColor = glm::dvec3(glm::vec3(value(MaterialParameter::SheenColor)));
    material.sheenRoughness = value(MaterialParameter::SheenRoughness).x;
    material.anisotropy = value(MaterialParameter::AnisotropyStrength).x;
    if (value(MaterialParameter::IridescenceFactor).x > 0.0f) {
        material.iridescence = value(MaterialParameter::IridescenceFactor).x;
        material.iridescenceIor = value(MaterialParameter::IridescenceIor).x;
        material.iridescenceThickness = value(MaterialParameter::IridescenceThickness).y; // the maximum: no textures
    }
    const render::FrameSettings& settings = viewer.settings();
    const render::ResolvedShading shading =
        render::resolveShading(settings.materialOverride, settings.brdfGeometry, render::packShading(renderer.materialShading(m)));
    const render::BrdfCurves curves = render::sampleBrdfCurves(material, shading, viewDegrees);
    const int n = int(curves.whole.size());
    ImGui::TextDisabled("material %d, factors only (textures are not sampled)", m);
    ImGui::TextDisabled("x: light angle -89..89 deg; mirror direction at +%.0f", viewDegrees);
    switch (curves.kind) {
    case render::BrdfPlotKind::None:
        ImGui::TextWrapped("%s shading does not depend on the light's direction: nothing to plot.", scene::shadingModelName(shading.model));
        break;
    case render::BrdfPlotKind::Classic: {
        const bool blinn = shading.model == scene::ShadingModel::BlinnPhong;
        ImGui::Text("%s: lobe %s, n = %.0f", scene::shadingModelName(shading.model), blinn ? "(N.H)^n" : "(R.V)^n", curves.shininess);
        ImGui::TextDisabled("f x NoL = (kd NoL + ks lobe) / pi");
        ImGui::PlotLines("lobe", curves.d.data(), n, 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 60));
        ImGui::PlotLines("f x NoL", curves.whole.data(), n, 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 60));
        break;
    }
    case render::BrdfPlotKind::Microfacet:
        ImGui::Text("D %s, G %s, F %s, diffuse %s", scene::brdfDistributionName(shading.distribution),
                    scene::brdfGeometryName(shading.geometry), scene::brdfFresnelName(shading.fresnel),
                    scene::brdfDiffuseName(shading.diffuse));
        ImGui::PlotLines("D", curves.d.data(), n, 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 60));
        ImGui::PlotLines("V = G/(4 NoL NoV)", curves.v.data(), n, 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 60));
        ImGui::PlotLines("F (luminance)", curves.f.data(), n, 0, nullptr, 0.0f, 1.0f, ImVec2(0, 60));
        if (material.iridescence > 0.0) {
            // The film's interference colours F: each channel apart.
            ImGui::PlotLines("F red (film)", curves.fRed.data(), n, 0, nullptr, 0.0f, 1.0f, ImVec2(0, 40));
            ImGui::PlotLines("F green (film)", curves.fGreen.data(), n, 0, nullptr, 0.0f, 1.0f, ImVec2(0, 40));
            ImGui::PlotLines("F blue (film)", curves.fBlue.data(), n, 0, nullptr, 0.0f, 1.0f, ImVec2(0, 40));
        }
        ImGui::PlotLines("f x NoL", curves.whole.data(), n, 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 60));
        if (!curves.sheen.empty())
            ImGui::PlotLines("sheen x NoL (Charlie)", curves.sheen.data(), int(curves.sheen.size()), 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 60));
        if (!curves.wholeAcross.empty()) {
            // KHR_materials_anisotropy: the curves above lie along the tangent; these across it.
            ImGui::TextDisabled("anisotropic: above along the tangent, below across it");
            ImGui::PlotLines("D across", curves.dAcross.data(), n, 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 60));
            ImGui::PlotLines("f x NoL across", curves.wholeAcross.data(), n, 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 60));
        }
        break;
    }
}

void environmentPanel(Viewer& viewer)
{
    if (!panelHeader(viewer, "Environment")) return;
    render::EnvironmentView& e = viewer.settings().environment;
    ImGui::Text("file: %s", viewer.environmentName().empty() ? "(none)" : viewer.environmentName().c_str());
    if (viewer.bakeProgress().pending) {
        // A bake the cache did not hold: the frames show its preview until the full one is in.
        ImGui::ProgressBar(float(viewer.bakeProgress().fraction), ImVec2(-1.0f, 0.0f), "baking (preview shown)");
    }
    std::array<char, 512>& path = viewer.environmentInput;
    ImGui::InputText("##envpath", path.data(), path.size());
    ImGui::SameLine();
    if (ImGui::Button("load")) viewer.openFile(path.data());
    ImGui::TextDisabled("or drop a .hdr / .exr on the window");
    ImGui::Checkbox("image-based lighting", &e.lighting);
    bool extract = viewer.sunExtraction();
    if (ImGui::Checkbox("sun as a light", &extract)) viewer.setSunExtraction(extract);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("--env-sun extract: the map's sun taken out and added as the light \"%s\"%s", setup::kEnvironmentSunName,
                          extract && !viewer.environmentSunExtracted() ? " (this map has none)" : "");
    if (ImGui::BeginCombo("specular", render::iblSpecularName(e.specular))) {
        for (auto mode : {render::IblSpecular::SplitSum, render::IblSpecular::Importance})
            if (ImGui::Selectable(render::iblSpecularName(mode), mode == e.specular)) e.specular = mode;
        ImGui::EndCombo();
    }
    ImGui::DragFloat("intensity", &e.intensity, 0.01f, 0.0f, 1e4f);
    ImGui::SliderFloat("rotation", &e.rotationDegrees, -180.0f, 180.0f, "%.0f deg");
    ImGui::Checkbox("skybox", &e.skybox);
    ImGui::SliderFloat("skybox blur", &e.skyboxBlur, 0.0f, 1.0f);
}

/// One widget for each row of a pass's table, over the table's slider range; an edit the
/// command line or the scene file would reject (out of range, out of order) is not taken.
/// A pass with only its switch (FXAA) is one checkbox, any other a tree (`open`: at first).
template <typename T>
void passWidgets(T& settings, bool open)
{
    const SettingsTable<T>& table = settingsTable<T>();
    ImGui::PushID(table.key);
    if (table.fields.size() == 1) {
        ImGui::Checkbox(table.title, &settings.enabled);
        ImGui::PopID();
        return;
    }
    if (!ImGui::TreeNodeEx(table.title, open ? ImGuiTreeNodeFlags_DefaultOpen : 0)) {
        ImGui::PopID();
        return;
    }
    for (const SettingField<T>& field : table.fields) {
        const std::string label = *field.label ? field.label : words(field.name);
        SettingRange slider = field.sliderRange();
        // An order keeps each end of a pair on its side of the other (as ImGui's range widgets do).
        for (const SettingOrder<T>& order : table.orders) {
            if (order.upper == field.member) slider.min = std::max(slider.min, table.find(order.lower)->value(settings));
            if (order.lower == field.member) slider.max = std::min(slider.max, table.find(order.upper)->value(settings));
        }
        std::visit(
            [&](auto member) {
                using V = SettingValue<decltype(member)>;
                V& value = settings.*member;
                V edited = value;
                bool changed = false;
                if constexpr (std::is_same_v<V, bool>) {
                    changed = ImGui::Checkbox(label.c_str(), &edited);
                } else if constexpr (std::is_same_v<V, int>) {
                    changed = ImGui::SliderInt(label.c_str(), &edited, int(slider.min), int(slider.max));
                } else {
                    changed = ImGui::SliderFloat(label.c_str(), &edited, float(slider.min), float(slider.max));
                }
                if (!changed || !field.range.contains(double(edited))) return;
                const V before = std::exchange(value, edited);
                for (const SettingOrder<T>& order : table.orders) {
                    const bool mine = order.lower == field.member || order.upper == field.member;
                    if (mine && !(table.find(order.lower)->value(settings) < table.find(order.upper)->value(settings))) value = before;
                }
            },
            field.member);
    }
    ImGui::TreePop();
    ImGui::PopID();
}

void postPanel(Viewer& viewer)
{
    if (!panelHeader(viewer, "Post-processing", ImGuiTreeNodeFlags_DefaultOpen)) return;
    render::FrameSettings& s = viewer.settings();
    ImGui::SliderFloat("exposure (EV)", &s.exposureEv, -10.0f, 10.0f);
    if (ImGui::BeginCombo("tone mapper", render::tonemapName(s.tonemap))) {
        for (auto t : {render::Tonemap::None, render::Tonemap::Reinhard, render::Tonemap::ReinhardExtended, render::Tonemap::Aces,
                       render::Tonemap::Neutral, render::Tonemap::Agx})
            if (ImGui::Selectable(render::tonemapName(t), t == s.tonemap)) s.tonemap = t;
        ImGui::EndCombo();
    }
    if (s.tonemap == render::Tonemap::ReinhardExtended) ImGui::DragFloat("white point", &s.reinhardWhite, 0.05f, 0.1f, 100.0f);
    {
        static constexpr int kSamples[] = {1, 2, 4, 8};
        int index = s.msaa >= 8 ? 3 : s.msaa >= 4 ? 2 : s.msaa >= 2 ? 1 : 0;
        if (ImGui::Combo("MSAA samples", &index, "1\0" "2\0" "4\0" "8\0")) s.msaa = kSamples[index];
    }
    ImGui::Checkbox("energy compensation", &s.energyCompensation);
    bool first = true;
    forEachPass([&](auto& pass) { passWidgets(pass, std::exchange(first, false)); }, s);
    if (ImGui::BeginCombo("transparency", render::transparencyName(s.transparency))) {
        for (auto t : {render::Transparency::Sorted, render::Transparency::Oit})
            if (ImGui::Selectable(render::transparencyName(t), t == s.transparency)) s.transparency = t;
        ImGui::EndCombo();
    }
    if (ImGui::BeginCombo("shadow quality", shadowQualityName(s.shadows.quality))) {
        for (auto q : {ShadowQuality::Low, ShadowQuality::Medium, ShadowQuality::High})
            if (ImGui::Selectable(shadowQualityName(q), q == s.shadows.quality)) s.shadows.quality = q;
        ImGui::EndCombo();
    }
    if (ImGui::BeginCombo("shadow filter", shadowFilterName(s.shadows.filter))) {
        for (auto f : {ShadowFilter::Hard, ShadowFilter::Pcf, ShadowFilter::Pcss})
            if (ImGui::Selectable(shadowFilterName(f), f == s.shadows.filter)) s.shadows.filter = f;
        ImGui::EndCombo();
    }
    // The atlas as the shadow-atlas debug view draws it (white: empty or far), redrawn while open.
    if (ImGui::TreeNode("shadow atlas")) {
        if (const uint32_t atlas = viewer.renderer().shadowAtlasImage(256))
            ImGui::Image(reinterpret_cast<ImTextureID>(uintptr_t(atlas)), ImVec2(256, 256), ImVec2(0, 1), ImVec2(1, 0));
        else
            ImGui::TextDisabled("no light has a shadow map");
        ImGui::TreePop();
    }
    if (ImGui::BeginCombo("debug view", debugViewName(s.debugView))) {
        // Every view up to the last one (BrdfF), material inputs and BRDF terms included.
        for (int k = 0; k <= int(kLastDebugView); ++k) {
            const auto d = DebugView(k);
            if (ImGui::Selectable(debugViewName(d), d == s.debugView)) s.debugView = d;
        }
        ImGui::EndCombo();
    }
}

} // namespace

void handleInput(Viewer& viewer, float deltaSeconds)
{
    const ImGuiIO& io = ImGui::GetIO();
    OrbitCamera& camera = viewer.camera();
    if (!io.WantCaptureMouse) {
        // Degrees per pixel dragged: half a turn across a 720-pixel-high window.
        constexpr float kDegreesPerPixel = 0.25f;
        const float height = std::max(io.DisplaySize.y, 1.0f);
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f) && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
            viewer.useCamera(-1);
            if (viewer.flyMode) {
                // Like a first-person game: drag right looks right, drag down looks down.
                camera.look(-io.MouseDelta.x * kDegreesPerPixel, io.MouseDelta.y * kDegreesPerPixel);
            } else {
                camera.orbit(-io.MouseDelta.x * kDegreesPerPixel, io.MouseDelta.y * kDegreesPerPixel);
            }
        }
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f)) {
            viewer.useCamera(-1);
            camera.pan(-io.MouseDelta.x / height, io.MouseDelta.y / height);
        }
        // A click without a drag picks the material under the cursor.
        if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] < 9.0f)
            viewer.pickMaterial(io.MousePos.x * io.DisplayFramebufferScale.x, io.MousePos.y * io.DisplayFramebufferScale.y);
        if (io.MouseWheel != 0.0f) {
            viewer.useCamera(-1);
            camera.zoom(std::pow(1.1f, io.MouseWheel));
        }
    }
    if (io.WantCaptureKeyboard) return;
    if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) {
        viewer.useCamera(-1);
        camera.frame(viewer.document().scene.worldBounds());
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) viewer.resetCamera();
    if (ImGui::IsKeyPressed(GLFW_KEY_P, false) || ImGui::IsKeyPressed(GLFW_KEY_F12, false)) {
        // Shift: the window as shown, panels included (written at the end of this frame).
        if (io.KeyShift) viewer.screenshotWindow(timestampedScreenshotName());
        else takeScreenshot(viewer);
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_H, false) || ImGui::IsKeyPressed(GLFW_KEY_TAB, false)) viewer.showUi = !viewer.showUi;
    if (ImGui::IsKeyPressed(GLFW_KEY_F5, false)) viewer.reloadShaders();
    if (ImGui::IsKeyPressed(GLFW_KEY_C, false)) viewer.flyMode = !viewer.flyMode;
    if (viewer.flyMode) {
        glm::vec3 move(0.0f);
        if (ImGui::IsKeyDown(GLFW_KEY_W)) move.z += 1.0f;
        if (ImGui::IsKeyDown(GLFW_KEY_S)) move.z -= 1.0f;
        if (ImGui::IsKeyDown(GLFW_KEY_D)) move.x += 1.0f;
        if (ImGui::IsKeyDown(GLFW_KEY_A)) move.x -= 1.0f;
        if (ImGui::IsKeyDown(GLFW_KEY_E)) move.y += 1.0f;
        if (ImGui::IsKeyDown(GLFW_KEY_Q)) move.y -= 1.0f;
        if (move != glm::vec3(0.0f)) {
            viewer.useCamera(-1);
            camera.move(move * camera.flySpeed() * deltaSeconds);
        }
    }
}

void drawUi(Viewer& viewer)
{
    if (!viewer.lastError.empty()) {
        // Errors stay on screen until dismissed, whether or not the panels are shown.
        // Bottom left, clear of the main panel; wide enough for a compile error's file and line.
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        ImGui::SetNextWindowPos(ImVec2(10, display.y - 10), ImGuiCond_Always, ImVec2(0, 1));
        ImGui::Begin("Error", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 110, 255));
        ImGui::PushTextWrapPos(std::max(200.0f, std::min(700.0f, display.x - 40.0f)));
        ImGui::TextUnformatted(viewer.lastError.c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopStyleColor();
        if (ImGui::Button("dismiss")) viewer.lastError.clear();
        ImGui::End();
    }
    if (!viewer.showUi) return;
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(420, std::max(300.0f, ImGui::GetIO().DisplaySize.y - 20.0f)), ImGuiCond_FirstUseEver);
    ImGui::Begin("Specula");
    ImGui::TextDisabled("F frame  R reset camera  C fly camera  H hide UI");
    ImGui::TextDisabled("P screenshot (Shift+P: with panels)  F5 reload shaders");
    if (!viewer.lastMessage.empty()) ImGui::TextWrapped("%s", viewer.lastMessage.c_str());
    statisticsPanel(viewer);
    scenePanel(viewer);
    animationPanel(viewer);
    lightsPanel(viewer);
    materialsPanel(viewer);
    brdfPanel(viewer);
    environmentPanel(viewer);
    postPanel(viewer);
    ImGui::End();
}

} // namespace specula::viewer
