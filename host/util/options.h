#pragma once
// Options that methods, solvers and solve strategies declare for themselves (as pbrt-v4's
// ParameterDictionary and Mitsuba's Properties let a plugin name what it reads): the code that
// uses an option declares it once, with its help, kind, default and range; the command line is
// made from those declarations (app/cli_options.cpp), and an option the chosen method or
// solver does not declare is refused rather than ignored. Nothing here knows about CLI11.

#include <array>
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
    Choice,    // one word of `choices`
    Colour,    // R,G,B or one number for all three, each finite and >= 0
};

struct OptionSpec {
    std::string name;  // as typed: "--hemicube-res"; without dashes, a positional argument ("SCENE")
    OptionKind kind = OptionKind::Count;
    std::string help;
    // Flag: 0. Count, Positive, Fraction: a default outside [min, max] (Positive: 0) means "not
    // given" (the reader derives one) and is not shown.
    double defaultValue = 0.0;
    double min = 0.0, max = 0.0;
    std::string defaultText;           // Text, Choice, Colour; Size (shown as given: "4G")
    std::vector<std::string> choices;  // Choice
    std::string placeholder;           // how the help shows the value (FILE.exr); empty: by kind
    std::string needs;                 // a flag without which this option is refused
    bool required = false;

    static OptionSpec flag(std::string name, std::string help) {
        return of(std::move(name), OptionKind::Flag, std::move(help));
    }
    static OptionSpec count(std::string name, std::string help, double value, double min, double max) {
        return of(std::move(name), OptionKind::Count, std::move(help), value, min, max);
    }
    // A positive number; a default of 0 means "not given" (the reader derives one).
    static OptionSpec positive(std::string name, std::string help, double value = 0.0) {
        return of(std::move(name), OptionKind::Positive, std::move(help), value);
    }
    static OptionSpec fraction(std::string name, std::string help, double value, double min, double max) {
        return of(std::move(name), OptionKind::Fraction, std::move(help), value, min, max);
    }
    static OptionSpec size(std::string name, std::string help, std::string value) {
        OptionSpec spec = of(std::move(name), OptionKind::Size, std::move(help));
        spec.defaultText = std::move(value);
        return spec;
    }
    static OptionSpec text(std::string name, std::string help, std::string value = "") {
        OptionSpec spec = of(std::move(name), OptionKind::Text, std::move(help));
        spec.defaultText = std::move(value);
        return spec;
    }
    static OptionSpec choice(std::string name, std::string help, std::string value, std::vector<std::string> choices) {
        OptionSpec spec = of(std::move(name), OptionKind::Choice, std::move(help));
        spec.defaultText = std::move(value);
        spec.choices = std::move(choices);
        return spec;
    }
    static OptionSpec colour(std::string name, std::string help) {
        return of(std::move(name), OptionKind::Colour, std::move(help));
    }

    OptionSpec shownAs(std::string shown) && {
        placeholder = std::move(shown);
        return std::move(*this);
    }
    OptionSpec needing(std::string flag) && {
        needs = std::move(flag);
        return std::move(*this);
    }
    OptionSpec mandatory() && {
        required = true;
        return std::move(*this);
    }

private:
    static OptionSpec of(std::string name, OptionKind kind, std::string help, double value = 0.0, double min = 0.0,
                         double max = 0.0) {
        OptionSpec spec;
        spec.name = std::move(name);
        spec.kind = kind;
        spec.help = std::move(help);
        spec.defaultValue = value;
        spec.min = min;
        spec.max = max;
        return spec;
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

// Parses a colour: "R,G,B" or one number for all three, each finite, >= 0 and at most 1e30;
// nothing on failure.
bool parseColour(const std::string& text, std::array<double, 3>& colour);

}  // namespace rad
