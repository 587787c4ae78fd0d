#pragma once
// Options that methods, solvers and solve strategies declare for themselves (as pbrt-v4's
// ParameterDictionary and Mitsuba's Properties let a plugin name what it reads): the code that
// uses an option declares it once, with its help, kind, default and range; the command line is
// made from those declarations (app/cli_options.cpp), and an option the chosen method or
// solver does not declare is refused rather than ignored. Nothing here knows about CLI11.

#include <cstdint>
#include <initializer_list>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace rad {

enum class OptionKind {
    Flag,      // present or not
    Count,     // a whole number in [min, max], written 16000000, 16e6 or 1.6e7
    Positive,  // a positive finite number
    Fraction,  // a number in [min, max]
    Size,      // bytes, with an optional K, M, G or T suffix (binary)
    Text,      // a word or a path
};

struct OptionSpec {
    std::string name;  // as typed: "--hemicube-res"
    OptionKind kind = OptionKind::Count;
    std::string help;
    double defaultValue = 0.0;  // Flag: 0; Text: unused
    double min = 0.0, max = 0.0;
    std::string defaultText;  // Text; Size (shown as given: "4G")

    static OptionSpec flag(std::string name, std::string help) {
        return {std::move(name), OptionKind::Flag, std::move(help), 0.0, 0.0, 0.0, ""};
    }
    static OptionSpec count(std::string name, std::string help, double value, double min, double max) {
        return {std::move(name), OptionKind::Count, std::move(help), value, min, max, ""};
    }
    // A positive number; a default of 0 means "not given" (the reader derives one).
    static OptionSpec positive(std::string name, std::string help, double value = 0.0) {
        return {std::move(name), OptionKind::Positive, std::move(help), value, 0.0, 0.0, ""};
    }
    static OptionSpec fraction(std::string name, std::string help, double value, double min, double max) {
        return {std::move(name), OptionKind::Fraction, std::move(help), value, min, max, ""};
    }
    static OptionSpec size(std::string name, std::string help, std::string value) {
        return {std::move(name), OptionKind::Size, std::move(help), 0.0, 0.0, 0.0, std::move(value)};
    }
    static OptionSpec text(std::string name, std::string help) {
        return {std::move(name), OptionKind::Text, std::move(help), 0.0, 0.0, 0.0, ""};
    }
};

// The values the user gave, by option name. Readers pass the spec, so a value not given reads
// as the spec's default.
class OptionValues {
public:
    OptionValues() = default;
    OptionValues(std::initializer_list<std::pair<const std::string, double>> numbers) : numbers_(numbers) {}

    void setNumber(const std::string& name, double value) { numbers_[name] = value; }
    void setText(const std::string& name, std::string value) { texts_[name] = std::move(value); }
    bool given(const std::string& name) const { return numbers_.count(name) > 0 || texts_.count(name) > 0; }

    double number(const OptionSpec& spec) const;
    bool flag(const OptionSpec& spec) const { return number(spec) != 0.0; }
    std::uint32_t count32(const OptionSpec& spec) const { return static_cast<std::uint32_t>(number(spec)); }
    std::uint64_t count64(const OptionSpec& spec) const { return static_cast<std::uint64_t>(number(spec)); }
    std::string text(const OptionSpec& spec) const;

private:
    std::map<std::string, double> numbers_;
    std::map<std::string, std::string> texts_;
};

// Parses a size: "4G", "512M", "1048576"; nothing on failure.
bool parseSize(const std::string& text, double& bytes);

}  // namespace rad
