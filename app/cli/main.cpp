// specula: the command line. Thin: parses arguments and calls the library.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "CommandLine.h"
#include "core/Error.h"
#include "core/Log.h"

using namespace specula;

int main(int argc, char** argv)
{
    log::init();
    cli::CommandLine line;
    CLI::App& app = line.app;

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }

    try {
        if (*line.renderCommand) return cli::runRender(line.render);
        if (*line.galleryCommand) return cli::runGallery(line.gallery);
        if (*line.infoCommand) return cli::runInfo();
        if (*line.benchCommand) return cli::runBench(line.bench);
        if (*line.bakeCommand) return cli::runBake(line.bake);
        if (*line.viewCommand) return viewer::runView(line.view);
    } catch (const Error& e) {
        std::fprintf(stderr, "specula: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "specula: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
