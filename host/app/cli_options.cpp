#include "app/cli_options.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "scene/closed_glass.h"
#include "scene/property_materials.h"
#include "scene/environment_map.h"
#include "scene/scene_files.h"
#include "util/error.h"

namespace rad {
namespace {

// The default the help shows; empty where there is none or it means "not given".
std::string defaultText(const OptionSpec& spec) {
    char text[64];
    switch (spec.kind) {
        case OptionKind::Count:
        case OptionKind::Fraction:
            if (!(spec.defaultValue >= spec.min && spec.defaultValue <= spec.max)) return "";
            std::snprintf(text, sizeof text, spec.kind == OptionKind::Count ? "%.0f" : "%g", spec.defaultValue);
            return text;
        case OptionKind::Positive:
            if (spec.defaultValue == 0.0) return "";
            std::snprintf(text, sizeof text, "%g", spec.defaultValue);
            return text;
        case OptionKind::Size:
        case OptionKind::Text:
        case OptionKind::Choice:
        case OptionKind::Colour:
            return spec.defaultText;
        case OptionKind::Flag:
            return "";
    }
    return "";
}

// A whole number in [min, max], written 16000000, 16e6 or 1.6e7.
CLI::Option* addWholeNumber(CLI::App* app, const std::string& name, std::function<void(double)> store,
                            const std::string& help, double min, double max) {
    return app
        ->add_option_function<double>(
            name,
            [store, name, min, max](const double& v) {
                if (!(v >= min && v <= max) || std::floor(v) != v) {
                    char range[96];
                    std::snprintf(range, sizeof range, "must be a whole number from %.0f to %.0f", min, max);
                    throw CLI::ValidationError(name, range);
                }
                store(v);
            },
            help)
        ->type_name("N");
}

// A positive finite number (CLI11's own PositiveNumber prints the whole range of double when it
// fails).
CLI::Option* addPositiveNumber(CLI::App* app, const std::string& name, std::function<void(double)> store,
                               const std::string& help) {
    return app
        ->add_option_function<double>(
            name,
            [store, name](const double& v) {
                if (!(v > 0.0) || !std::isfinite(v)) throw CLI::ValidationError(name, "must be a positive number");
                store(v);
            },
            help)
        ->type_name("X");
}

void requireKind(const OptionSpec& spec, std::initializer_list<OptionKind> kinds) {
    if (std::find(kinds.begin(), kinds.end(), spec.kind) == kinds.end())
        throw std::logic_error(spec.name + " is bound to a field of another kind than it declares");
}

glm::vec3 toColour(const std::array<double, 3>& c) {
    return glm::vec3(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]));
}

std::string listed(const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t k = 0; k < items.size(); ++k)
        out += (k == 0 ? "" : k + 1 == items.size() ? " or " : ", ") + items[k];
    return out;
}

}  // namespace

std::string SceneFileArgs::name() const {
    std::string joined;
    for (std::size_t k = 0; k < files.size(); ++k) joined += (k ? ", " : "") + files[k];
    return joined;
}

void addSceneFileOptions(DeclaredOptions& options, SceneFileArgs& args) {
    options.bind(OptionSpec::text("SCENE", "the scene: one glTF file (.gltf, .glb), or OBJ (with its MTL), STL and PLY "
                                           "files, read together")
                     .mandatory(),
                 args.files);
    options.bind(OptionSpec::choice("--unit", "length unit of OBJ, STL and PLY coordinates (glTF is in metres)", "m",
                                    {"m", "cm", "mm", "in", "ft"}),
                 args.unit);
}

Scene loadScene(const SceneFileArgs& args) { return loadScene(args.files, args.unit); }

void addThreadsOption(CLI::App* command, std::uint32_t& threads) {
    DeclaredOptions(command).bind(
        OptionSpec::count("--threads",
                          "threads of the CPU device (PoCL); 0: POCL_MAX_PTHREAD_COUNT if set, else every core. "
                          "The results are the same at any count",
                          0, 0, 4096),
        threads);
}

void applyThreads(std::uint32_t threads) {
    if (threads == 0) return;
    // PoCL 3 reads the first; later releases name it the second.
    setenv("POCL_MAX_PTHREAD_COUNT", std::to_string(threads).c_str(), 1);
    setenv("POCL_CPU_MAX_CU_COUNT", std::to_string(threads).c_str(), 1);
}

void addSceneInputOptions(DeclaredOptions& options, SceneInputArgs& args) {
    addSceneFileOptions(options, args.scene);
    options.bind(OptionSpec::positive("--patch-size",
                                      "longest patch edge in metres (default: 1/32 of the scene's diagonal)"),
                 args.patchSize);
    options.bind(OptionSpec::count("--seed", "seed of the sample sequences; the same seed gives the same numbers", 1, 0,
                                   4294967295.0),
                 args.seed);
    options.bind(OptionSpec::text("--device",
                                  "OpenCL device: index, cpu, gpu, or part of its name (see 'devices'); under mpirun a "
                                  "comma-separated list gives rank r entry r mod its length (one GPU per rank: 0,1,2,3)"),
                 args.device);
    options.bind(OptionSpec::count("--max-patches", "refuse meshes with more patches than this", 10'000'000, 1, 1e12),
                 args.maxPatches);
}

std::string deviceForRank(const std::string& devices, int rank) {
    std::vector<std::string> entries;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = devices.find(',', start);
        entries.push_back(devices.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return entries[static_cast<std::size_t>(rank) % entries.size()];
}

void addLightingOptions(DeclaredOptions& options, LightingArgs& args) {
    options.bind(OptionSpec::colour("--sky", "a uniform sky: radiance R,G,B (W/m^2/sr) from every direction a ray "
                                             "leaves the scene in"),
                 args.sky);
    options.bind(OptionSpec::text("--environment",
                                  "an equirectangular OpenEXR map (W/m^2/sr) of the light from every direction a ray "
                                  "leaves the scene in, mapped as Blender's Environment Texture maps it (glTF +Y up)")
                     .shownAs("FILE.exr"),
                 args.environment);
    options.bind(OptionSpec::positive("--environment-strength",
                                      "multiplies the environment map's radiance (Blender's Background strength)", 1.0),
                 args.environmentStrength);
    options.bind(OptionSpec::text("--properties",
                                  "set surfaces' diffuse reflectance and emitted radiance (W/m^2/sr) from a CSV file: "
                                  "surface,reflectance,emission (or reflectance_r,_g,_b and emission_r,_g,_b); the "
                                  "file exchange reads serves too")
                     .shownAs("FILE.csv"),
                 args.properties);
    options.bind(OptionSpec::flag("--solid-glass",
                                  "draw glass without KHR_materials_volume (transmission 1) as the solid its closed "
                                  "mesh bounds, refracting, as Cycles draws Blender's glass, rather than as glTF's "
                                  "thin wall (open meshes stay thin, with a warning)"),
                 args.solidGlass);
}

void applyLighting(const LightingArgs& args, Scene& scene) {
    if (!args.properties.empty()) applyPropertyMaterials(scene, args.properties);
    if (args.solidGlass) solidifyClosedGlass(scene);
    if (!args.environment.empty() && args.sky != glm::vec3(0.0f))
        throw InputError("--sky and --environment both say what lies outside the scene: give one of them");
    scene.sky = args.sky;
    if (!args.environment.empty())
        scene.environment =
            std::make_shared<const EnvironmentMap>(loadEnvironmentMap(args.environment, args.environmentStrength));
}

void refuseUnlitScene(const std::string& path, const std::string& consequence) {
    throw FileError(path,
                    "nothing lights the scene: no material has an emissive factor, it places no "
                    "KHR_lights_punctual light, and neither --sky nor --environment was given (nor an emission by "
                    "--properties): " +
                        consequence);
}

CLI::Option* DeclaredOptions::make(const OptionSpec& spec, std::function<void(double)> number,
                                   std::function<void(const std::string&)> text) {
    const std::string& name = spec.name;
    if (added_.count(name)) throw std::logic_error(name + " is declared twice on one command");
    CLI::Option* option = nullptr;
    switch (spec.kind) {
        case OptionKind::Flag:
            option = command_->add_flag_callback(
                name, [number] { number(1.0); }, spec.help);
            break;
        case OptionKind::Text:
            option = command_->add_option_function<std::string>(name, text, spec.help)->type_name("TEXT");
            break;
        case OptionKind::Choice:
            option = command_->add_option_function<std::string>(name, text, spec.help)->check(CLI::IsMember(spec.choices));
            break;
        case OptionKind::Colour:
            option = command_
                         ->add_option_function<std::string>(
                             name,
                             [text, name](const std::string& v) {
                                 std::array<double, 3> colour{};
                                 if (!parseColour(v, colour))
                                     throw CLI::ValidationError(name, "must be R,G,B (or one number): radiances >= 0 in W/m^2/sr");
                                 text(v);
                             },
                             spec.help)
                         ->type_name("R,G,B");
            break;
        case OptionKind::Count:
            option = addWholeNumber(command_, name, number, spec.help, spec.min, spec.max);
            break;
        case OptionKind::Positive:
            option = addPositiveNumber(command_, name, number, spec.help);
            break;
        case OptionKind::Fraction:
            option = command_->add_option_function<double>(name, number, spec.help)
                         ->check(CLI::Range(spec.min, spec.max))
                         ->type_name("X");
            break;
        case OptionKind::Size:
            // Bytes, with an optional binary suffix: 4G, 512M, 1048576.
            option = command_
                         ->add_option_function<std::string>(
                             name,
                             [number, name](const std::string& v) {
                                 double bytes = 0.0;
                                 if (!parseSize(v, bytes))
                                     throw CLI::ValidationError(name, "must be a size such as 4G, 512M or 1048576");
                                 number(static_cast<double>(static_cast<std::uint64_t>(bytes)));
                             },
                             spec.help)
                         ->type_name("SIZE");
            break;
    }
    if (!spec.placeholder.empty()) option->type_name(spec.placeholder);
    const std::string shown = defaultText(spec);
    if (!shown.empty()) option->default_str(shown);
    if (!spec.needs.empty()) {
        const auto needed = added_.find(spec.needs);
        if (needed == added_.end()) throw std::logic_error(name + " needs " + spec.needs + ", declared after it");
        option->needs(needed->second);
    }
    if (spec.required) option->required();
    added_[name] = option;
    return option;
}

void DeclaredOptions::bind(const OptionSpec& spec, bool& field) {
    requireKind(spec, {OptionKind::Flag});
    field = false;
    make(spec, [&field](double v) { field = v != 0.0; }, nullptr);
}

void DeclaredOptions::bind(const OptionSpec& spec, std::string& field) {
    requireKind(spec, {OptionKind::Text, OptionKind::Choice});
    field = spec.defaultText;
    make(spec, nullptr, [&field](const std::string& v) { field = v; });
}

void DeclaredOptions::bind(const OptionSpec& spec, std::vector<std::string>& field) {
    requireKind(spec, {OptionKind::Text});
    if (spec.name.rfind("-", 0) == 0) throw std::logic_error(spec.name + ": only a positional argument takes a list");
    if (added_.count(spec.name)) throw std::logic_error(spec.name + " is declared twice on one command");
    field.clear();
    CLI::Option* option = command_->add_option(spec.name, field, spec.help)->expected(1, -1)->type_name("FILE");
    if (spec.required) option->required();
    added_[spec.name] = option;
}

void DeclaredOptions::bind(const OptionSpec& spec, glm::vec3& field) {
    requireKind(spec, {OptionKind::Colour});
    std::array<double, 3> colour{};
    if (!spec.defaultText.empty() && !parseColour(spec.defaultText, colour))
        throw std::logic_error(spec.name + "'s default is not a colour");
    field = toColour(colour);
    make(spec, nullptr, [&field](const std::string& v) {
        std::array<double, 3> given{};
        parseColour(v, given);  // checked as it was parsed
        field = toColour(given);
    });
}

void DeclaredOptions::bindNumber(const OptionSpec& spec, std::function<void(double)> store) {
    requireKind(spec, {OptionKind::Count, OptionKind::Positive, OptionKind::Fraction, OptionKind::Size});
    store(OptionValues().number(spec));
    make(spec, std::move(store), nullptr);
}

void DeclaredOptions::bind(const OptionSpec& spec, double& field) {
    bindNumber(spec, [&field](double v) { field = v; });
}

void DeclaredOptions::bind(const OptionSpec& spec, int& field) {
    bindNumber(spec, [&field](double v) { field = static_cast<int>(v); });
}

void DeclaredOptions::bind(const OptionSpec& spec, std::uint32_t& field) {
    bindNumber(spec, [&field](double v) { field = static_cast<std::uint32_t>(v); });
}

void DeclaredOptions::bind(const OptionSpec& spec, std::uint64_t& field) {
    bindNumber(spec, [&field](double v) { field = static_cast<std::uint64_t>(v); });
}

void DeclaredOptions::add(const std::vector<OptionSpec>& specs, const std::string& owner) {
    if (!values_) throw std::logic_error("options added to a command that keeps no option values");
    for (const OptionSpec& spec : specs) {
        if (added_.count(spec.name) && !owners_.count(spec.name))
            throw std::logic_error(spec.name + " is both the command's own option and a declared one");
        auto& owners = owners_[spec.name];
        if (std::find(owners.begin(), owners.end(), owner) == owners.end()) owners.push_back(owner);
        if (added_.count(spec.name)) continue;
        OptionValues* values = values_;
        const std::string name = spec.name;
        make(
            spec, [values, name](double v) { values->setNumber(name, v); },
            [values, name](const std::string& v) { values->setText(name, v); });
    }
}

void DeclaredOptions::refuseUnused(const std::vector<OptionSpec>& used, const std::string& chosen) const {
    for (const auto& entry : owners_) {
        const std::string& name = entry.first;
        if (added_.at(name)->count() == 0) continue;
        const bool read = std::any_of(used.begin(), used.end(), [&](const OptionSpec& s) { return s.name == name; });
        if (read) continue;
        throw InputError(name + " is not used by " + chosen + "; it is an option of " + listed(entry.second));
    }
}

}  // namespace rad
