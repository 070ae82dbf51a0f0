// The command line: the input is the arguments, one per line, parsed by the specula binary's
// own grammar (app/cli/CommandLine.h), then validated as a render would (resolveSettings on an
// empty scene; no GL, no files). A rejected argument must be a CLI11 ParseError or a
// specula::Error; anything else, any sanitizer report, is a finding.
// The grammar is built once (building it is most of an input's time: 44 inputs a second under
// AddressSanitizer when each built its own) and put back to its state after construction before
// each input: CLI11's clear() forgets the last parse, and the arguments it wrote into are
// restored from a copy taken when it was new, so every input starts from the same parser.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "CommandLine.h"
#include "FuzzSupport.h"
#include "core/Error.h"
#include "setup/SceneSetup.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    specula::fuzz::quietLogs();
    std::vector<std::string> args;
    std::string current;
    for (size_t i = 0; i < size && args.size() < 64; ++i) {
        if (data[i] == '\n') {
            args.push_back(current);
            current.clear();
        } else {
            current += char(data[i]);
        }
    }
    if (!current.empty()) args.push_back(current);
    std::reverse(args.begin(), args.end()); // CLI11 takes them last first

    static specula::cli::CommandLine line;
    static const specula::cli::RenderArgs render = line.render;
    static const specula::cli::BenchArgs bench = line.bench;
    static const specula::cli::BakeArgs bake = line.bake;
    static const specula::viewer::ViewArgs view = line.view;
    static const specula::cli::GalleryArgs gallery = line.gallery;
    line.app.clear();
    line.render = render;
    line.bench = bench;
    line.bake = bake;
    line.view = view;
    line.gallery = gallery;
    try {
        line.app.parse(args);
    } catch (const CLI::ParseError&) {
        return 0;
    }
    const specula::scene::SceneDocument document;
    const auto check = [&](const specula::setup::FrameOptions& frame) {
        try {
            specula::setup::resolveSettings(document, frame);
            specula::setup::resolveBakeSettings(frame);
        } catch (const specula::Error&) {
        }
    };
    if (*line.renderCommand) check(line.render.frame);
    if (*line.benchCommand) check(line.bench.frame);
    if (*line.galleryCommand) check(line.gallery.frame);
    if (*line.viewCommand) check(line.view.frame);
    return 0;
}
