#include "PostOptions.h"

#include <CLI/CLI.hpp>

#include <type_traits>
#include <variant>

namespace specula::cli {

void addPostOptions(CLI::App* command, setup::FrameOptions& options)
{
    forEachPass(
        [&](auto& flags) {
            using T = typename std::decay_t<decltype(flags)>::Settings;
            const SettingsTable<T>& table = settingsTable<T>();
            for (const SettingField<T>& field : table.fields) {
                if (!field.commandLine) continue;
                const std::string flag = "--" + flagName(table, field);
                const std::string help = commandLineHelp(field);
                std::visit(
                    [&](auto member) {
                        using V = SettingValue<decltype(member)>;
                        if constexpr (std::is_same_v<V, bool>) {
                            command->add_option_function<std::string>(
                                       flag, [&flags, member](const std::string& value) { flags.set(member, value == "on"); }, help)
                                ->check(CLI::IsMember({"on", "off"}));
                        } else {
                            command->add_option_function<V>(flag, [&flags, member](const V& value) { flags.set(member, value); }, help);
                        }
                    },
                    field.member);
            }
        },
        options.post);
    command->add_option("--ev100", options.ev100, "physical camera exposure 1 / (1.2 x 2^EV100), times 2^--exposure");
    command->add_option("--shadow-quality", options.shadowQuality, "shadow map resolution and kernel: low, medium (default), high")
        ->check(CLI::IsMember({"low", "medium", "high"}));
    command->add_option("--shadow-filter", options.shadowFilter,
                        "shadow filter: hard, pcf (default: a 3x3 tent of texel comparisons in 4 bilinear taps; high quality 5x5), pcss (soft shadows from the light's size)")
        ->check(CLI::IsMember({"hard", "pcf", "pcss"}));
}

} // namespace specula::cli
