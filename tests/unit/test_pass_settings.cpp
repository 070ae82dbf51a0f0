// The passes' settings tables (settings/PassSettings.h): each lists every member of its struct,
// its defaults are the struct's initialisers and lie in its ranges, the scene file accepts
// exactly its names, and an out-of-range value from the scene file or from the command line
// (as setup::resolveSettings checks it) gives the table's one-line message.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "TestFiles.h"
#include "scene/SceneFile.h"
#include "settings/PassSettings.h"
#include "setup/SceneSetup.h"

using namespace specula;

namespace {

/// Converts to anything: T{AnyValue{}, ...} compiles for as many values as T has members.
struct AnyValue {
    template <typename V>
    constexpr operator V() const
    {
        return V{};
    }
};

template <typename T, typename... Values>
constexpr size_t memberCount()
{
    if constexpr (requires { T{Values{}..., AnyValue{}}; }) {
        return memberCount<T, Values..., AnyValue>();
    } else {
        return sizeof...(Values);
    }
}

/// Calls f(table, initialised) for each pass's table, with a T of its own initialisers (static,
/// as GCC cannot follow a member pointer into a temporary's bytes and warns them uninitialised).
template <typename F>
void forEachTable(F&& f)
{
    PostOverrides none;
    forEachPass([&](auto& pass) {
        using T = typename std::decay_t<decltype(pass)>::Settings;
        static const T initialised{};
        f(settingsTable<T>(), initialised);
    }, none);
}

/// A value outside the range, on the side that is bounded (nullopt: any finite number).
std::optional<double> outside(const SettingRange& range)
{
    if (std::isfinite(range.min)) return range.minExclusive ? range.min : range.min - 1.0;
    if (std::isfinite(range.max)) return range.max + 1.0;
    return std::nullopt;
}

/// The value as a JSON literal.
std::string json(SettingKind kind, double value)
{
    if (kind == SettingKind::Bool) return value != 0.0 ? "true" : "false";
    return fmt::format("{}", value);
}

} // namespace

TEST(PassSettings, TablesListEveryMember)
{
    EXPECT_EQ(settingsTable<BloomSettings>().fields.size(), memberCount<BloomSettings>());
    EXPECT_EQ(settingsTable<SsaoSettings>().fields.size(), memberCount<SsaoSettings>());
    EXPECT_EQ(settingsTable<FxaaSettings>().fields.size(), memberCount<FxaaSettings>());
    // deltaTime is the frame's clock (the viewer's), not a setting: no row.
    EXPECT_EQ(settingsTable<AutoExposureSettings>().fields.size() + 1, memberCount<AutoExposureSettings>());
    EXPECT_FALSE(settingsTable<AutoExposureSettings>().find(&AutoExposureSettings::deltaTime));
}

TEST(PassSettings, RowsAreWellFormed)
{
    std::set<std::string> keys;
    forEachTable([&](const auto& table, const auto& defaults) {
        EXPECT_TRUE(keys.insert(table.key).second) << table.key;
        ASSERT_FALSE(table.fields.empty());
        EXPECT_STREQ(table.fields[0].name, "enabled") << table.key << ": the switch comes first";
        EXPECT_EQ(table.fields[0].kind(), SettingKind::Bool);
        // Shadows are on by default; every post pass is off.
        EXPECT_EQ(table.fields[0].defaultValue(), std::string(table.key) == "shadows" ? 1.0 : 0.0) << table.key << ": default switch";
        std::set<std::string> names;
        for (const auto& field : table.fields) {
            SCOPED_TRACE(std::string(table.key) + "." + field.name);
            EXPECT_TRUE(names.insert(field.name).second) << "duplicate name";
            EXPECT_EQ(table.find(field.member), &field) << "two rows of one member";
            EXPECT_EQ(table.findFlag(flagName(table, field)), &field);
            EXPECT_EQ(field.defaultValue(), field.value(defaults));
            if (field.kind() == SettingKind::Bool) continue;
            EXPECT_TRUE(field.range.contains(field.defaultValue())) << "default " << field.defaultValue() << " out of its range";
            // The viewer's slider: bounded, inside the range, around the default.
            const SettingRange slider = field.sliderRange();
            EXPECT_TRUE(slider.bounded());
            EXPECT_TRUE(field.range.contains(slider.max));
            EXPECT_TRUE(slider.min >= field.range.min);
            EXPECT_TRUE(field.defaultValue() >= slider.min && field.defaultValue() <= slider.max);
        }
        for (const auto& order : table.orders) {
            ASSERT_TRUE(table.find(order.lower) && table.find(order.upper));
            EXPECT_LT(table.find(order.lower)->defaultValue(), table.find(order.upper)->defaultValue());
        }
    });
}

TEST(PassSettings, HelpShowsTheInitialiser)
{
    forEachTable([&](const auto& table, const auto& defaults) {
        for (const auto& field : table.fields) {
            const std::string help = commandLineHelp(field);
            const std::string expected = "(default " + formatSetting(field.kind(), field.value(defaults)) + ")";
            EXPECT_TRUE(help.ends_with(expected)) << flagName(table, field) << ": " << help;
        }
    });
    const auto& bloom = settingsTable<BloomSettings>();
    EXPECT_EQ(commandLineHelp(*bloom.find("levels")), "down-sampled levels, each doubling the glow's reach, 1 to 8 (default 6)");
    EXPECT_EQ(commandLineHelp(*bloom.find("intensity")), "fraction of the frame's energy added as glow (default 0.04)");
    EXPECT_EQ(commandLineHelp(*bloom.find("enabled")), "bloom (compute shaders): on or off (default off)");
    EXPECT_EQ(commandLineHelp(*settingsTable<SsaoSettings>().find("bias")), "depth bias in metres (default 0.025)");
}

TEST(PassSettings, FlagsAreTodays)
{
    std::vector<std::string> flags;
    forEachTable([&](const auto& table, const auto&) {
        for (const auto& field : table.fields)
            if (field.commandLine) flags.push_back(flagName(table, field));
    });
    const std::vector<std::string> expected = {"shadows", "shadows-cascades", "shadows-cascade-split", "shadows-distance",
                                               "shadows-cascade-blend", "shadows-normal-bias", "shadows-slope-bias",
                                               "shadows-constant-bias", "shadows-max-lights", "shadows-max-directional",
                                               "shadows-light-size", "shadows-cache", "shadows-tint", "bloom", "bloom-intensity", "bloom-levels", "bloom-radius", "bloom-threshold",
                                               "bloom-knee", "bloom-firefly-filter", "ssao", "ssao-radius", "ssao-bias",
                                               "ssao-power", "ssao-samples", "fxaa", "auto-exposure"};
    EXPECT_EQ(flags, expected);
}

TEST(PassSettings, RangesInWords)
{
    EXPECT_EQ(SettingRange::positive().requirement(), "must be positive");
    EXPECT_EQ(SettingRange::nonNegative().requirement(), "must not be negative");
    EXPECT_EQ(SettingRange::between(1, 8).requirement(), "must be between 1 and 8");
    EXPECT_EQ(SettingRange::between(0, 1).requirement(), "must be between 0 and 1");
    EXPECT_EQ(SettingRange::any().requirement(), "must be a finite number");
    EXPECT_FALSE(SettingRange::positive().contains(0.0));
    EXPECT_FALSE(SettingRange::nonNegative().contains(std::nan("")));
    EXPECT_FALSE(SettingRange::any().contains(INFINITY));
    EXPECT_TRUE(SettingRange::any().contains(-1e30));
}

TEST(PassSettings, SceneFileAcceptsExactlyTheTablesNames)
{
    forEachTable([&](const auto& table, const auto& defaults) {
        using T = std::decay_t<decltype(defaults)>;
        // Every row's key, at its default: read back as given.
        std::string members;
        for (const auto& field : table.fields)
            members += fmt::format("{}\"{}\": {}", members.empty() ? "" : ", ", field.name, json(field.kind(), field.defaultValue()));
        const std::string text = fmt::format(R"({{"post": {{"{}": {{{}}}}}}})", table.key, members);
        const scene::SceneDocument document = test::loadSceneText(text);
        const SettingsOverride<T>* read = nullptr;
        forEachPass([&](const auto& pass) {
            if constexpr (std::is_same_v<std::decay_t<decltype(pass)>, SettingsOverride<T>>) read = &pass;
        }, document.post);
        ASSERT_TRUE(read);
        EXPECT_EQ(read->members().size(), table.fields.size()) << text;
        for (const auto& field : table.fields)
            EXPECT_EQ(field.value(read->values()), field.defaultValue()) << table.key << "." << field.name;
        // Anything else is an unknown key.
        const std::string unknown = test::sceneError(fmt::format(R"({{"post": {{"{}": {{"notAField": 1}}}}}})", table.key));
        EXPECT_NE(unknown.find(fmt::format("unknown key 'notAField' in post.{}", table.key)), std::string::npos) << unknown;
    });
    EXPECT_NE(test::sceneError(R"({"post": {"autoExposure": {"deltaTime": 0.1}}})").find("unknown key 'deltaTime' in post.autoExposure"),
              std::string::npos);
    EXPECT_NE(test::sceneError(R"({"post": {"tonemap": true}})").find("unknown key 'tonemap' in post"), std::string::npos);
}

TEST(PassSettings, OutOfRangeInTheSceneFile)
{
    forEachTable([&](const auto& table, const auto&) {
        for (const auto& field : table.fields) {
            const std::optional<double> bad = outside(field.range);
            if (field.kind() == SettingKind::Bool || !bad) continue;
            const std::string message =
                test::sceneError(fmt::format(R"({{"post": {{"{}": {{"{}": {}}}}}}})", table.key, field.name, *bad));
            const std::string expected = fmt::format("post.{}.{} {}", table.key, field.name, field.range.requirement());
            EXPECT_NE(message.find(expected), std::string::npos) << "expected '" << expected << "' in: " << message;
        }
    });
    EXPECT_NE(test::sceneError(R"({"post": {"autoExposure": {"lowPercentile": 0.5, "highPercentile": 0.4}}})")
                  .find("post.autoExposure.lowPercentile must be less than highPercentile (defaults 0.1 and 0.95)"),
              std::string::npos);
    EXPECT_NE(test::sceneError(R"({"post": {"autoExposure": {"maxEv100": -7}}})")
                  .find("post.autoExposure.minEv100 must be less than maxEv100 (defaults -6 and 18)"),
              std::string::npos);
}

TEST(PassSettings, OutOfRangeOnTheCommandLine)
{
    const scene::SceneDocument document;
    int checked = 0;
    forEachTable([&](const auto& table, const auto& defaults) {
        using T = std::decay_t<decltype(defaults)>;
        for (const auto& field : table.fields) {
            const std::optional<double> bad = outside(field.range);
            if (!field.commandLine || field.kind() == SettingKind::Bool || !bad) continue;
            setup::FrameOptions options;
            forEachPass([&](auto& flags) {
                if constexpr (std::is_same_v<std::decay_t<decltype(flags)>, SettingsOverride<T>>)
                    std::visit([&](auto member) {
                        using V = SettingValue<decltype(member)>;
                        flags.set(member, V(*bad));
                    }, field.member);
            }, options.post);
            const std::string message = test::errorOf([&] { setup::resolveSettings(document, options); });
            EXPECT_EQ(message, fmt::format("--{} {} (got {})", flagName(table, field), field.range.requirement(), *bad));
            ++checked;
        }
    });
    EXPECT_EQ(checked, 19); // every numeric flag has a bound
}

TEST(PassSettings, SourcesLayerOverDefaults)
{
    // Nothing set: the initialisers.
    const render::FrameSettings plain = setup::resolveSettings(scene::SceneDocument{}, setup::FrameOptions{});
    forEachPass([&](const auto& pass) {
        using T = std::decay_t<decltype(pass)>;
        for (const auto& field : settingsTable<T>().fields) EXPECT_EQ(field.value(pass), field.defaultValue()) << field.name;
    }, plain);
    // The file over the defaults, the command line over the file, field by field.
    const scene::SceneDocument document = test::loadSceneText(R"({"post": {"bloom": {"intensity": 0.5, "levels": 3}}})");
    setup::FrameOptions options;
    options.post.bloom.set(&BloomSettings::levels, 7);
    options.post.ssao.set(&SsaoSettings::enabled, true);
    const render::FrameSettings s = setup::resolveSettings(document, options);
    EXPECT_TRUE(s.bloom.enabled);
    EXPECT_EQ(s.bloom.intensity, 0.5f);
    EXPECT_EQ(s.bloom.levels, 7);
    EXPECT_EQ(s.bloom.radius, BloomSettings{}.radius);
    EXPECT_TRUE(s.ssao.enabled);
    EXPECT_FALSE(s.fxaa.enabled);
}
