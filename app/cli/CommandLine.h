#pragma once
// The command line's grammar: every subcommand and flag, parsed into the commands' arguments.
// Apart from main() so that the argument-parsing fuzzer (fuzz/fuzz_cli.cpp) runs the same parser.
#include <CLI/CLI.hpp>

#include "Commands.h"
#include "app/viewer/ViewCommand.h"

namespace specula::cli {

struct CommandLine {
    CommandLine();
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    CLI::App app{"Specula: a physically based renderer (OpenGL 4.5)", "specula"};
    RenderArgs render;
    BenchArgs bench;
    BakeArgs bake;
    viewer::ViewArgs view;
    GalleryArgs gallery;
    CLI::App* renderCommand = nullptr;
    CLI::App* infoCommand = nullptr;
    CLI::App* benchCommand = nullptr;
    CLI::App* bakeCommand = nullptr;
    CLI::App* viewCommand = nullptr;
    CLI::App* galleryCommand = nullptr;
};

} // namespace specula::cli
