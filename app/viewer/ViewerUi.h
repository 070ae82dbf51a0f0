#pragma once
// The viewer's Dear ImGui panels and its mouse and keyboard handling.
struct GLFWwindow;

namespace specula::viewer {

class Viewer;

/// Mouse (orbit, pan, zoom; fly look) and keys (F frame, R reset camera, P screenshot, Shift+P
/// with the panels, H toggle UI, F5 reload shaders, C fly camera, WASD/QE fly) the UI did not take.
void handleInput(Viewer& viewer, float deltaSeconds);
/// Every panel: Statistics, Scene, Lights, Materials, Environment, Post-processing, BRDF explorer.
void drawUi(Viewer& viewer);

} // namespace specula::viewer
