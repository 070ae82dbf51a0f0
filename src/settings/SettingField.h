#pragma once
// A pass's settings as a table: one row per field (its name, help, member, range), read by the
// command line (flags and their checks), the scene file's "post" object and the viewer's
// widgets, so that a field is declared once, with one set of limits and one wording of them.
//
// The directory src/settings/ is a layer of its own, below scene and render and free of GL:
// the scene file parses these settings, the renderer reads them and the apps edit them, and
// none of those may include the others (scene must not see render). Its types live in namespace
// specula, beside core's Error and images, as vocabulary every layer above shares; that also
// keeps the render passes' unqualified `BloomSettings` meaning what it did.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace specula {

/// The values a field accepts: [min, max], or (min, max] with `minExclusive`. The command line
/// and the scene file reject any other value with the same words, requirement().
struct SettingRange {
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
    double min = -kInfinity;
    double max = kInfinity;
    bool minExclusive = false;

    /// Any finite number.
    static constexpr SettingRange any() { return {}; }
    /// > 0.
    static constexpr SettingRange positive() { return {0.0, kInfinity, true}; }
    /// ≥ 0.
    static constexpr SettingRange nonNegative() { return {0.0, kInfinity, false}; }
    static constexpr SettingRange between(double lo, double hi) { return {lo, hi, false}; }

    bool isAny() const { return std::isinf(min) && std::isinf(max); }
    bool bounded() const { return std::isfinite(min) && std::isfinite(max); }
    /// NaN is in no range; infinity only in an unbounded one that is not any().
    bool contains(double value) const
    {
        if (isAny()) return std::isfinite(value);
        return (minExclusive ? value > min : value >= min) && value <= max;
    }
    /// "must be positive", "must be between 1 and 8": what an error says after the name.
    std::string requirement() const;
    /// "1 to 8" for a bounded range, else empty: the command line's help.
    std::string span() const;
};

/// The member a field reads and writes; its type is the field's kind (on/off, integer, number).
template <typename T>
using SettingMember = std::variant<bool T::*, int T::*, float T::*>;

/// The value type of a member pointer: float for `float T::*`.
template <typename M>
struct SettingValueOf;
template <typename T, typename V>
struct SettingValueOf<V T::*> {
    using type = V;
};
template <typename M>
using SettingValue = typename SettingValueOf<M>::type;

/// Whether a `M` (V T::*) can name a member of T at all: none is larger than its struct. The
/// visits below skip the alternatives that cannot (FxaaSettings is one bool, so its int and
/// float ones), which GCC's -Warray-bounds flags when it sees a read through them.
template <typename T, typename M>
constexpr bool kCanBeMember = sizeof(SettingValue<M>) <= sizeof(T);

/// T's initialisers, once. (Static: read through a member pointer, a temporary T{} looks partly
/// uninitialised to GCC's -Wmaybe-uninitialized, which cannot tell which bytes are read.)
template <typename T>
const T& settingDefaults()
{
    static const T defaults{};
    return defaults;
}

enum class SettingKind { Bool, Int, Float };

/// One row of a pass's table. Its default is the struct's initialiser (T{}), never written here.
template <typename T>
struct SettingField {
    /// The scene-file key (camelCase). The command-line flag is the pass's key and this name in
    /// kebab case (--bloom-firefly-filter); the field "enabled" is the pass's switch (--bloom).
    const char* name;
    SettingMember<T> member;
    /// What it does, one phrase: --help appends "1 to 8" for a bounded range and the default.
    const char* help;
    /// What the command line and the scene file accept; the viewer keeps edits inside it.
    SettingRange range = {};
    /// The viewer's slider, where `range` is not bounded on both sides (then it must be given).
    SettingRange slider = {};
    /// The viewer's label; empty: the name's words ("fireflyFilter" → "firefly filter").
    const char* label = "";
    /// False for a field only the scene file and the viewer set (it has no flag).
    bool commandLine = true;

    SettingKind kind() const { return SettingKind(member.index()); }
    /// The field's value in `settings` as a number (true = 1).
    double value(const T& settings) const
    {
        return std::visit(
            [&](auto m) {
                if constexpr (kCanBeMember<T, decltype(m)>) return double(settings.*m);
                else return 0.0;
            },
            member);
    }
    double defaultValue() const { return value(settingDefaults<T>()); }
    /// The viewer's slider range: `slider` where given, else `range`.
    SettingRange sliderRange() const { return slider.bounded() ? slider : range; }
};

/// Two fields whose values must be in order, `lower` < `upper` (an EV100 range), checked on the
/// scene file's values with the defaults filling in the one it omits.
template <typename T>
struct SettingOrder {
    SettingMember<T> lower, upper;
};

/// A pass's table. Every table has a bool field "enabled": the pass's switch.
template <typename T>
struct SettingsTable {
    const char* key;   ///< the pass's key in the scene file's "post" object (camelCase)
    const char* title; ///< the viewer's heading
    std::span<const SettingField<T>> fields;
    std::span<const SettingOrder<T>> orders = {};

    const SettingField<T>* find(std::string_view name) const
    {
        const auto it = std::find_if(fields.begin(), fields.end(), [&](const SettingField<T>& f) { return name == f.name; });
        return it == fields.end() ? nullptr : &*it;
    }
    const SettingField<T>* find(const SettingMember<T>& member) const
    {
        const auto it = std::find_if(fields.begin(), fields.end(), [&](const SettingField<T>& f) { return f.member == member; });
        return it == fields.end() ? nullptr : &*it;
    }
    /// The field whose flag, without its dashes, is `flag` ("bloom-intensity", "bloom").
    const SettingField<T>* findFlag(std::string_view flag) const;
};

/// "autoExposure" → "auto-exposure".
std::string kebabCase(std::string_view camelCase);
/// "fireflyFilter" → "firefly filter".
std::string words(std::string_view camelCase);
/// A flag without its dashes: "bloom-intensity", or "bloom" for the field "enabled".
std::string flagName(std::string_view passKey, std::string_view fieldName);
/// The command line's help: the field's phrase, the range of a bounded number and the default
/// ("... 1 to 8 (default 6)", "...: on or off (default off)").
std::string commandLineHelp(SettingKind kind, const char* help, const SettingRange& range, double defaultValue);
/// A default or a limit as messages print it: "0.04", "6", "on".
std::string formatSetting(SettingKind kind, double value);

template <typename T>
std::string flagName(const SettingsTable<T>& table, const SettingField<T>& field)
{
    return flagName(table.key, field.name);
}

template <typename T>
std::string commandLineHelp(const SettingField<T>& field)
{
    return commandLineHelp(field.kind(), field.help, field.range, field.defaultValue());
}

template <typename T>
const SettingField<T>* SettingsTable<T>::findFlag(std::string_view flag) const
{
    const auto it = std::find_if(fields.begin(), fields.end(), [&](const SettingField<T>& f) { return flag == flagName(key, f.name); });
    return it == fields.end() ? nullptr : &*it;
}

/// What one source (the scene file, the command line) sets of a pass's settings; the others
/// keep what the source below gave, down to the struct's initialisers.
template <typename T>
class SettingsOverride {
public:
    using Settings = T;

    template <typename V>
    void set(V T::*member, V value)
    {
        mValues.*member = value;
        if (!has(member)) mSet.emplace_back(member);
    }
    template <typename V>
    bool has(V T::*member) const
    {
        return std::find(mSet.begin(), mSet.end(), SettingMember<T>(member)) != mSet.end();
    }
    template <typename V>
    std::optional<V> get(V T::*member) const
    {
        return has(member) ? std::optional<V>(mValues.*member) : std::nullopt;
    }
    bool empty() const { return mSet.empty(); }
    /// The members set, in the order they were set.
    const std::vector<SettingMember<T>>& members() const { return mSet; }
    /// This source's values, valid at members() only.
    const T& values() const { return mValues; }
    /// Writes every value this source sets into `settings`.
    void applyTo(T& settings) const
    {
        for (const SettingMember<T>& member : mSet)
            std::visit([&](auto m) { if constexpr (kCanBeMember<T, decltype(m)>) settings.*m = mValues.*m; }, member);
    }

private:
    T mValues{};
    std::vector<SettingMember<T>> mSet;
};

} // namespace specula
