#pragma once
/// \file
/// Specula's public API in one include. A program that renders with Specula:
///
/// - makes an OpenGL 4.5 context current: platform::Context::createHeadless() (EGL, no display
///   needed) or platform::Context::createWindow() (GLFW);
/// - loads a scene: scene::loadGltf() (.gltf, .glb), scene::loadScene() (also Specula's .json
///   scene files), or setup::loadSceneOrBuiltin() (also the built-in scenes such as "demo");
/// - gives it to a render::Renderer with setScene(), optionally an environment for image-based
///   lighting with setEnvironment() (render::loadEnvironmentMap(), render::proceduralSky());
/// - renders a render::View (render::defaultView() frames the scene or uses its camera) with
///   render::FrameSettings, and reads the frame back with readImage() or readRadiance();
/// - writes it with writePng(), writeHdr() or writeExr().
///
/// Errors caused by input or by the machine (a bad file, no GL context) are thrown as
/// specula::Error with a one-line message. No header here includes or names an OpenGL type.
/// docs/api.md has a complete example.
#include "Version.h"
#include "core/Error.h"
#include "core/ImageIO.h"
#include "platform/Context.h"
#include "render/BakeSettings.h"
#include "render/PlacedLight.h"
#include "render/Renderer.h"
#include "render/View.h"
#include "scene/GltfImporter.h"
#include "scene/Scene.h"
#include "scene/SceneFile.h"
#include "settings/PassSettings.h"
#include "setup/SceneSetup.h"
#include "shading/EnvironmentMap.h"
#include "shading/SunExtraction.h"
#include "shading/Tonemap.h"
