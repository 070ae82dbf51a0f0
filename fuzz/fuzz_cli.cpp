// The command line: the input is the arguments, one per line, parsed by the specula binary's
// own grammar (app/cli/CommandLine.h), then validated as a render would (resolveSettings on an
// empty scene; no GL, no files). A rejected argument must be a CLI11 ParseError or a
// specula::Error; anything else, any sanitizer report, is a finding.
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

    specula::cli::CommandLine line;
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
