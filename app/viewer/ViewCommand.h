#pragma once
// `specula view`: an interactive window on a scene (Dear ImGui panels), scriptable for tests.
#include <string>

#include "setup/SceneSetup.h"

namespace specula::viewer {

struct ViewArgs {
    std::string scene;
    setup::FrameOptions frame;
    int frames = 0;          ///< > 0: render this many frames (after the script), then exit
    std::string screenshot;  ///< with --frames: the last frame as PNG
    std::string script;      ///< UI actions to replay (docs/viewer.md)
    bool hideUi = false;
};

int runView(const ViewArgs& args);

} // namespace specula::viewer
