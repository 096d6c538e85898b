#include "core/program/linuxcnc_ini.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "core/common/field_error.h"
#include "core/common/number_format.h"

namespace probecycle {

namespace {

// Templates in context "LinuxCncIni", like every text of this file.
Message ini_message(const char* code, const char* text, std::vector<MessageArg> args = {}) {
    return Message{code, "LinuxCncIni", text, std::move(args)};
}

// --- the file as LinuxCNC's IniFile reads it -------------------------------

struct IniValue {
    std::size_t line{0};
    std::optional<std::string> value;  // nullopt: no '=' or nothing after it
};

struct IniSection {
    std::map<std::string, IniValue, std::less<>> keys;  // each key's first line
};

struct IniFile {
    std::map<std::string, IniSection, std::less<>> sections;  // each section's first block
    std::vector<std::size_t> include_lines;
};

// LinuxCNC's IniFile joins at most this many continued lines.
constexpr int kMaxContinuedLines = 20;

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

std::string_view trim(std::string_view text) {
    while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
    while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
    return text;
}

// "#INCLUDE file" as LinuxCNC's start script finds it: the line's first word.
bool is_include(std::string_view line) {
    constexpr std::string_view kInclude = "#INCLUDE";
    return line.starts_with(kInclude) &&
           (line.size() == kInclude.size() || is_blank(line[kInclude.size()]));
}

IniFile parse_ini(std::string_view text) {
    IniFile file;
    IniSection* section = nullptr;  // nullptr: before the first section, or a later block
    std::size_t number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        // One logical line: physical lines ending in '\' go on in the next.
        const std::size_t first_line = number + 1;
        std::string logical;
        for (int continued = 0;; ++continued) {
            std::size_t end = text.find('\n', start);
            if (end == std::string_view::npos) end = text.size();
            std::string_view line = text.substr(start, end - start);
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            ++number;
            start = end + 1;
            if (line.ends_with('\\') && continued < kMaxContinuedLines && start < text.size()) {
                logical += line.substr(0, line.size() - 1);
                continue;
            }
            logical += line;
            break;
        }
        const std::string_view line = trim(logical);
        if (is_include(line)) {
            file.include_lines.push_back(first_line);
            continue;
        }
        if (line.empty() || line.front() == '#' || line.front() == ';') continue;
        if (line.front() == '[') {
            // Any '[' line ends the block a key is looked up in.
            const std::size_t close = line.find(']');
            section = nullptr;
            if (close == std::string_view::npos) continue;
            const std::string name(line.substr(1, close - 1));
            if (file.sections.contains(name)) continue;  // a later block: LinuxCNC never reads it
            section = &file.sections[name];
            continue;
        }
        if (section == nullptr) continue;
        // A name alone on its line is no line of that key for LinuxCNC.
        const std::size_t key_end = line.find_first_of(" \t=");
        if (key_end == std::string_view::npos) continue;
        const std::string key(line.substr(0, key_end));
        if (section->keys.contains(key)) continue;  // the first line of a key wins
        IniValue& entry = section->keys[key];
        entry.line = first_line;
        const std::size_t equal = line.find('=', key_end);
        if (equal == std::string_view::npos) continue;
        const std::string_view value = trim(line.substr(equal + 1));
        if (!value.empty()) entry.value = std::string(value);
    }
    return file;
}

// --- what ProbeCycle takes from it -----------------------------------------

constexpr double kMmPerInch = 25.4;
// Results rounded to this many significant digits: an INI gives a few, and
// 20 in/s^2 reads 508 mm/s^2, not 507.99999999999994.
constexpr int kResultDigits = 12;

// Through the decimal text, so a value at either end of the doubles' range
// (4.9e-324, whose power of ten overflows a scale factor) rounds too.
double rounded(double value) {
    if (!std::isfinite(value)) return value;
    std::array<char, 32> text{};
    const auto written = std::to_chars(text.data(), text.data() + text.size(), value,
                                       std::chars_format::general, kResultDigits);
    double result = value;
    std::from_chars(text.data(), written.ptr, result);
    return result;
}

// Within [min, max]; a NaN is not.
bool within(double value, double min, double max) {
    return value >= min && value <= max;
}

// A unit of a number from a micrometre to a metre: LinuxCNC takes any
// positive number, but outside these a machine's figures overflow or vanish.
constexpr double kMinUnitsPerMm = 0.001;
constexpr double kMaxUnitsPerMm = 1000.0;

// [TRAJ] LINEAR_UNITS: what LinuxCNC accepts (emcIniFile.cc, linearUnitsMap,
// any case), or a number of units per mm.
struct LinearUnits {
    double mm_per_unit{1.0};
    std::string name;  // "mm", "in", or "units" for a number other than those
};

constexpr std::array<std::pair<std::string_view, double>, 5> kUnitWords = {
    {{"mm", 1.0},
     {"metric", 1.0},
     {"in", kMmPerInch},
     {"inch", kMmPerInch},
     {"imperial", kMmPerInch}}};

bool same_word(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c; };
               return lower(x) == lower(y);
           });
}

std::optional<LinearUnits> linear_units_from(std::string_view value) {
    for (const auto& [word, mm] : kUnitWords) {
        if (same_word(value, word)) return LinearUnits{mm, mm == 1.0 ? "mm" : "in"};
    }
    const std::optional<double> per_mm = parse_decimal(value);
    if (!per_mm || !within(*per_mm, kMinUnitsPerMm, kMaxUnitsPerMm)) return std::nullopt;
    const double mm = 1.0 / *per_mm;
    if (std::abs(mm - 1.0) < 1e-9) return LinearUnits{1.0, "mm"};
    if (std::abs(mm / kMmPerInch - 1.0) < 1e-6) return LinearUnits{kMmPerInch, "in"};
    return LinearUnits{mm, "units"};
}

// A value as the message shows it: a long one by its start.
std::string shown(const std::string& value) {
    if (value.size() <= kMaxShownValueChars) return value;
    std::size_t cut = kShownStartChars;
    while (cut > 0 && (static_cast<unsigned char>(value[cut]) & 0xC0) == 0x80) --cut;  // UTF-8
    return value.substr(0, cut) + "...";
}

// The range of an INI value whose machine key is `scale` times it, in the
// INI's units: rounded inward to the 6 digits a message shows, so every value
// it shows is accepted.
Message ini_range(const KeyInfo& key, double scale, const std::string& unit) {
    const auto step = [](double value) {
        return std::pow(10.0, std::floor(std::log10(std::abs(value))) - 5.0);
    };
    const double min = key.min / scale;
    const double max = key.max / scale;
    return range_allowed(round_up_to(min, step(min)), round_down_to(max, step(max)), unit.c_str());
}

Message a_decimal_number() {
    return ini_message("not_a_number", QT_TRANSLATE_NOOP("LinuxCncIni", "a decimal number"));
}

class Reader {
  public:
    explicit Reader(const IniFile& file) : file_(file) {}

    // The section, or nullptr after naming it missing with the keys it must give.
    const IniSection* section(const std::string& name, const char* keys, const char* gives) {
        const auto it = file_.sections.find(name);
        if (it != file_.sections.end()) return &it->second;
        problems_.push_back(
            {name, "", 0,
             ini_message("linuxcnc_ini_missing_section",
                         QT_TRANSLATE_NOOP("LinuxCncIni", "missing section; expected %1 (for %2)"),
                         {text_arg("keys", keys), text_arg("gives", gives)})});
        return nullptr;
    }

    // The section, or nullptr when the file has none (nothing to name).
    const IniSection* optional_section(const std::string& name) const {
        const auto it = file_.sections.find(name);
        return it != file_.sections.end() ? &it->second : nullptr;
    }

    // The value of a key, or nullopt after naming it missing or empty
    // (`required`) with what it must be.
    std::optional<IniValue> value(const std::string& section_name, const IniSection& section,
                                  const std::string& key, const Message& expected,
                                  const char* gives, bool required = true) {
        const auto it = section.keys.find(key);
        if (it == section.keys.end()) {
            if (!required) return std::nullopt;
            problems_.push_back(
                {section_name, key, 0,
                 ini_message("linuxcnc_ini_missing_key",
                             QT_TRANSLATE_NOOP("LinuxCncIni", "missing; expected %1 (for %2)"),
                             {message_arg("expected", expected), text_arg("gives", gives)})});
            return std::nullopt;
        }
        if (!it->second.value) {
            problems_.push_back(
                {section_name, key, it->second.line,
                 ini_message("linuxcnc_ini_no_value",
                             QT_TRANSLATE_NOOP("LinuxCncIni", "no value; expected %1 (for %2)"),
                             {message_arg("expected", expected), text_arg("gives", gives)})});
            return std::nullopt;
        }
        return it->second;
    }

    void refuse(const std::string& section_name, const std::string& key, const IniValue& entry,
                const Message& allowed, const char* gives) {
        problems_.push_back(
            {section_name, key, entry.line,
             ini_message("linuxcnc_ini_bad_value",
                         QT_TRANSLATE_NOOP("LinuxCncIni", "got %1; allowed: %2 (for %3)"),
                         {text_arg("value", shown(*entry.value)), message_arg("allowed", allowed),
                          text_arg("gives", gives)})});
    }

    std::vector<IniProblem>& problems() { return problems_; }

  private:
    const IniFile& file_;
    std::vector<IniProblem> problems_;
};

// A number read from the INI, with where it stands.
struct IniNumber {
    std::string section;
    std::string key;
    IniValue entry;
    double value{0.0};
};

constexpr std::array<const char*, 3> kAxes = {"AXIS_X", "AXIS_Y", "AXIS_Z"};
constexpr const char* kRapidKey = "machine.rapid_feed_mm_min";
constexpr const char* kAccelKey = "machine.max_accel_mm_s2";
constexpr const char* kPeriodGives = "machine.scan_period_s, machine.controller_latency_s";
constexpr const char* kUnitsGives = "machine.max_accel_mm_s2, machine.rapid_feed_mm_min";
constexpr const char* kBlockChangeGives = "machine.block_change_s";
// [TASK] CYCLE_TIME when the file has none: LinuxCNC's own default,
// DEFAULT_EMC_TASK_CYCLE_TIME in src/emc/nml_intf/emccfg.h.
constexpr double kDefaultTaskCycle_s = 0.100;
constexpr double kMinTaskCycle_s = 0.0001;
constexpr double kMaxTaskCycle_s = 0.5;
// The block change, fitted to LinuxCNC 2.9 running our programs (tests/linuxcnc,
// servo periods of 0.5, 1 and 2 ms, task cycles of 1, 2 and 10 ms): two servo
// periods at each move's ends, and on average 1.6 task cycles of waiting for
// the next block (after a probing move the interpreter waits for the motion
// to end before it reads the skip position). Per block the measurements lay
// within about 1 ms (2 ms at a 10 ms task cycle) of it.
constexpr double kBlockServoPeriods = 2.0;
constexpr double kBlockTaskCycles = 1.6;

}  // namespace

Message IniProblem::to_message() const {
    if (section.empty()) {
        return ini_message(problem.code.c_str(), QT_TRANSLATE_NOOP("LinuxCncIni", "line %1: %2"),
                           {arg("line", ArgKind::integer, static_cast<double>(line)),
                            message_arg("problem", problem)});
    }
    if (key.empty()) {
        return ini_message(problem.code.c_str(), QT_TRANSLATE_NOOP("LinuxCncIni", "[%1]: %2"),
                           {text_arg("section", section), message_arg("problem", problem)});
    }
    if (line == 0) {
        return ini_message(
            problem.code.c_str(), QT_TRANSLATE_NOOP("LinuxCncIni", "[%1] %2: %3"),
            {text_arg("section", section), text_arg("key", key), message_arg("problem", problem)});
    }
    return ini_message(problem.code.c_str(),
                       QT_TRANSLATE_NOOP("LinuxCncIni", "[%1] %2, line %3: %4"),
                       {text_arg("section", section), text_arg("key", key),
                        arg("line", ArgKind::integer, static_cast<double>(line)),
                        message_arg("problem", problem)});
}

namespace {
std::string join_problems(const std::vector<IniProblem>& problems) {
    std::string text;
    for (const IniProblem& p : problems) {
        if (!text.empty()) text += '\n';
        text += render(p.to_message());
    }
    return text;
}
}  // namespace

LinuxCncIniError::LinuxCncIniError(std::vector<IniProblem> problems)
    : std::runtime_error(join_problems(problems)), problems_(std::move(problems)) {}

Machine machine_from_linuxcnc_ini(std::string_view text) {
    const IniFile file = parse_ini(text);
    if (!file.include_lines.empty()) {
        // What follows from an include would be named missing: say only this.
        std::vector<IniProblem> problems;
        for (const std::size_t line : file.include_lines) {
            problems.push_back(
                {"", "", line,
                 ini_message("linuxcnc_ini_include",
                             QT_TRANSLATE_NOOP("LinuxCncIni",
                                               "#INCLUDE is not followed; LinuxCNC writes the "
                                               "configuration with its includes to NAME.ini."
                                               "expanded beside the INI file when it starts: "
                                               "read that file"))});
        }
        throw LinuxCncIniError(std::move(problems));
    }

    Reader reader(file);
    const KeyInfo& accel_key = *find_key(kAccelKey);
    const KeyInfo& rapid_key = *find_key(kRapidKey);
    const KeyInfo& scan_key = *find_key("machine.scan_period_s");
    const KeyInfo& latency_key = *find_key("machine.controller_latency_s");

    // [EMCMOT] SERVO_PERIOD: motmod's servo_period_nsec, a whole number of ns.
    // The latency is two periods, so both keys' ranges bound it.
    const double max_period_ns = std::min(scan_key.max, latency_key.max / 2.0) * 1e9;
    Message period_allowed = ini_message(
        "out_of_range", QT_TRANSLATE_NOOP("LinuxCncIni", "a whole number from %1 to %2 ns"),
        {arg("min", ArgKind::integer, 1.0), arg("max", ArgKind::integer, max_period_ns)});
    std::optional<double> period_ns;
    if (const IniSection* emcmot = reader.section("EMCMOT", "SERVO_PERIOD", kPeriodGives)) {
        if (const auto entry =
                reader.value("EMCMOT", *emcmot, "SERVO_PERIOD", period_allowed, kPeriodGives)) {
            const std::optional<double> ns = parse_decimal(*entry->value);
            if (ns && *ns == std::floor(*ns) && *ns >= 1.0 && *ns <= max_period_ns) {
                period_ns = *ns;
            } else {
                reader.refuse("EMCMOT", "SERVO_PERIOD", *entry, period_allowed, kPeriodGives);
            }
        }
    }

    // [TASK] CYCLE_TIME, the task's period: how long a block waits for the next.
    Message cycle_allowed = range_allowed(kMinTaskCycle_s, kMaxTaskCycle_s, "s");
    double task_cycle_s = kDefaultTaskCycle_s;
    if (const IniSection* task = reader.optional_section("TASK")) {
        if (const auto entry = reader.value("TASK", *task, "CYCLE_TIME", cycle_allowed,
                                            kBlockChangeGives, false)) {
            const std::optional<double> seconds = parse_decimal(*entry->value);
            if (seconds && *seconds >= kMinTaskCycle_s && *seconds <= kMaxTaskCycle_s) {
                task_cycle_s = *seconds;
            } else {
                reader.refuse("TASK", "CYCLE_TIME", *entry, cycle_allowed, kBlockChangeGives);
            }
        }
    }

    // [TRAJ] LINEAR_UNITS, and the optional cap on every move's speed.
    Message units_allowed = ini_message(
        "unknown_word",
        QT_TRANSLATE_NOOP("LinuxCncIni", "one of %1, or a number of units per mm from %2 to %3"),
        {text_arg("allowed_words", "mm, metric, in, inch, imperial"),
         arg("min", ArgKind::number, kMinUnitsPerMm), arg("max", ArgKind::number, kMaxUnitsPerMm)});
    std::optional<LinearUnits> units;
    std::vector<IniNumber> speeds;  // [TRAJ]'s cap, then the axes'
    std::vector<IniNumber> accels;
    const IniSection* traj = reader.section("TRAJ", "LINEAR_UNITS", kUnitsGives);
    if (traj != nullptr) {
        if (const auto entry =
                reader.value("TRAJ", *traj, "LINEAR_UNITS", units_allowed, kUnitsGives)) {
            units = linear_units_from(*entry->value);
            if (!units) reader.refuse("TRAJ", "LINEAR_UNITS", *entry, units_allowed, kUnitsGives);
        }
    }
    // The range of a speed or an acceleration in the INI's units, once they are known.
    const auto speed_allowed = [&] {
        return units ? ini_range(rapid_key, 60.0 * units->mm_per_unit, units->name + "/s")
                     : a_decimal_number();
    };
    const auto accel_allowed = [&] {
        return units ? ini_range(accel_key, units->mm_per_unit, units->name + "/s^2")
                     : a_decimal_number();
    };
    const auto read_number = [&](const std::string& section_name, const IniSection& section,
                                 const std::string& key, const Message& allowed, const char* gives,
                                 std::vector<IniNumber>& into, bool required) {
        const auto entry = reader.value(section_name, section, key, allowed, gives, required);
        if (!entry) return false;
        if (const std::optional<double> number = parse_decimal(*entry->value)) {
            into.push_back({section_name, key, *entry, *number});
        } else {
            reader.refuse(section_name, key, *entry, allowed, gives);
        }
        return true;
    };
    if (traj != nullptr && !read_number("TRAJ", *traj, "MAX_LINEAR_VELOCITY", speed_allowed(),
                                        kRapidKey, speeds, false)) {
        read_number("TRAJ", *traj, "MAX_VELOCITY", speed_allowed(), kRapidKey, speeds, false);
    }
    for (const char* axis : kAxes) {
        const IniSection* section =
            reader.section(axis, "MAX_VELOCITY, MAX_ACCELERATION", kUnitsGives);
        if (section == nullptr) continue;
        read_number(axis, *section, "MAX_VELOCITY", speed_allowed(), kRapidKey, speeds, true);
        read_number(axis, *section, "MAX_ACCELERATION", accel_allowed(), kAccelKey, accels, true);
    }

    // The smallest of each, checked against its machine key's range and named
    // where it stands when it is out of it.
    std::vector<IniProblem>& problems = reader.problems();
    const auto smallest = [](const std::vector<IniNumber>& numbers) {
        return std::min_element(
            numbers.begin(), numbers.end(),
            [](const IniNumber& a, const IniNumber& b) { return a.value < b.value; });
    };
    Machine machine;
    if (problems.empty() && units && period_ns && !speeds.empty() && !accels.empty()) {
        const auto speed = smallest(speeds);
        const auto accel = smallest(accels);
        machine.rapid_feed_mm_min = rounded(60.0 * speed->value * units->mm_per_unit);
        machine.max_accel_mm_s2 = rounded(accel->value * units->mm_per_unit);
        if (!within(machine.rapid_feed_mm_min, rapid_key.min, rapid_key.max)) {
            reader.refuse(speed->section, speed->key, speed->entry, speed_allowed(), kRapidKey);
        }
        if (!within(machine.max_accel_mm_s2, accel_key.min, accel_key.max)) {
            reader.refuse(accel->section, accel->key, accel->entry, accel_allowed(), kAccelKey);
        }
    }
    if (!problems.empty() || !units || !period_ns) throw LinuxCncIniError(std::move(problems));
    machine.accel_model = AccelModel::constant_accel;
    machine.filter = FilterKind::none;
    machine.servo_time_constant_s = 0.0;
    machine.scan_period_s = *period_ns / 1e9;
    machine.controller_latency_s = 2.0 * machine.scan_period_s;
    machine.latched_input = false;
    machine.block_change_s =
        rounded(kBlockServoPeriods * machine.scan_period_s + kBlockTaskCycles * task_cycle_s);
    return machine;
}

}  // namespace probecycle
