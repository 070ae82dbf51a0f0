#pragma once
// Command-line flags of the post-processing passes, shared by every rendering command: one
// flag per row of each pass's table (settings/PassSettings.h), and --ev100.
#include "setup/SceneSetup.h"

namespace CLI {
class App;
}

namespace specula::cli {

/// Adds --bloom, --bloom-intensity, ... (each table's command-line fields) and --ev100; their
/// values land in options.post and options.ev100, and setup::resolveSettings checks them.
void addPostOptions(CLI::App* command, setup::FrameOptions& options);

} // namespace specula::cli
