#include "app/cli_options.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "scene/environment_map.h"
#include "util/error.h"

namespace rad {
namespace {

std::string defaultText(const OptionSpec& spec) {
    char text[64];
    switch (spec.kind) {
        case OptionKind::Count:
            std::snprintf(text, sizeof text, "%.0f", spec.defaultValue);
            return text;
        case OptionKind::Positive:
        case OptionKind::Fraction:
            if (spec.defaultValue == 0.0 && spec.kind == OptionKind::Positive) return "";
            std::snprintf(text, sizeof text, "%g", spec.defaultValue);
            return text;
        case OptionKind::Size:
        case OptionKind::Text:
            return spec.defaultText;
        case OptionKind::Flag:
            return "";
    }
    return "";
}

CLI::Option* addOption(CLI::App* app, const OptionSpec& spec, OptionValues& values) {
    const std::string name = spec.name;
    switch (spec.kind) {
        case OptionKind::Flag:
            return app->add_flag_callback(
                name, [&values, name] { values.setNumber(name, 1.0); }, spec.help);
        case OptionKind::Text:
            return app
                ->add_option_function<std::string>(
                    name, [&values, name](const std::string& v) { values.setText(name, v); }, spec.help)
                ->type_name("TEXT");
        case OptionKind::Count:
            return addWholeNumber(
                app, name, [&values, name](double v) { values.setNumber(name, v); }, spec.help, spec.min, spec.max);
        case OptionKind::Positive:
            return addPositiveNumber(
                app, name, [&values, name](double v) { values.setNumber(name, v); }, spec.help);
        case OptionKind::Fraction:
            return app
                ->add_option_function<double>(
                    name, [&values, name](const double& v) { values.setNumber(name, v); }, spec.help)
                ->check(CLI::Range(spec.min, spec.max))
                ->type_name("X");
        case OptionKind::Size:
            // Bytes, with an optional binary suffix: 4G, 512M, 1048576.
            return app
                ->add_option_function<std::string>(
                    name,
                    [&values, name](const std::string& text) {
                        double bytes = 0.0;
                        if (!parseSize(text, bytes))
                            throw CLI::ValidationError(name, "must be a size such as 4G, 512M or 1048576");
                        values.setNumber(name, static_cast<double>(static_cast<std::uint64_t>(bytes)));
                    },
                    spec.help)
                ->type_name("SIZE");
    }
    return nullptr;
}

std::string listed(const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t k = 0; k < items.size(); ++k)
        out += (k == 0 ? "" : k + 1 == items.size() ? " or " : ", ") + items[k];
    return out;
}

}  // namespace

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

CLI::Option* addPositiveNumber(CLI::App* app, const std::string& name, std::function<void(double)> store,
                               const std::string& help) {
    // CLI11's own PositiveNumber prints the whole range of double when it fails.
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

void addSceneInputOptions(CLI::App* command, SceneInputArgs& args) {
    command->add_option("SCENE", args.scene, "glTF scene (.gltf or .glb)")->required();
    addPositiveNumber(
        command, "--patch-size", [&args](double v) { args.patchSize = v; },
        "longest patch edge in metres (default: 1/32 of the scene's diagonal)");
    command->add_option("--seed", args.seed, "seed of the sample sequences; the same seed gives the same numbers")
        ->capture_default_str();
    command->add_option("--device", args.device,
                        "OpenCL device: index, cpu, gpu, or part of its name (see 'devices'); under mpirun a comma-"
                        "separated list gives rank r entry r mod its length (one GPU per rank: 0,1,2,3)");
    addWholeNumber(
        command, "--max-patches", [&args](double v) { args.maxPatches = static_cast<std::uint64_t>(v); },
        "refuse meshes with more patches than this", 1, 1e12)
        ->default_str(std::to_string(args.maxPatches));
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

void addLightingOptions(CLI::App* command, LightingArgs& args) {
    command
        ->add_option_function<std::string>(
            "--sky",
            [&args](const std::string& text) {
                // R,G,B or one number for all three: finite and >= 0.
                std::vector<float> values;
                std::size_t start = 0;
                while (start <= text.size()) {
                    const std::size_t end = std::min(text.find(',', start), text.size());
                    const std::string part = text.substr(start, end - start);
                    char* stop = nullptr;
                    const double v = std::strtod(part.c_str(), &stop);
                    if (part.empty() || stop != part.c_str() + part.size() || !std::isfinite(v) || v < 0.0 || v > 1e30)
                        throw CLI::ValidationError("--sky",
                                                   "must be R,G,B (or one number): radiances >= 0 in W/m^2/sr");
                    values.push_back(static_cast<float>(v));
                    start = end + 1;
                }
                if (values.size() == 1) values.assign(3, values[0]);
                if (values.size() != 3)
                    throw CLI::ValidationError("--sky", "must be R,G,B (or one number): radiances >= 0 in W/m^2/sr");
                args.sky = glm::vec3(values[0], values[1], values[2]);
            },
            "a uniform sky: radiance R,G,B (W/m^2/sr) from every direction a ray leaves the scene in")
        ->type_name("R,G,B");
    command
        ->add_option("--environment", args.environment,
                     "an equirectangular OpenEXR map (W/m^2/sr) of the light from every direction a ray leaves "
                     "the scene in, mapped as Blender's Environment Texture maps it (glTF +Y up)")
        ->type_name("FILE.exr");
    addPositiveNumber(
        command, "--environment-strength", [&args](double v) { args.environmentStrength = v; },
        "multiplies the environment map's radiance (Blender's Background strength)")
        ->default_str("1");
}

void applyLighting(const LightingArgs& args, Scene& scene) {
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
                    "KHR_lights_punctual light, and neither --sky nor --environment was given: " +
                        consequence);
}

void DeclaredOptions::add(const std::vector<OptionSpec>& specs, const std::string& owner) {
    for (const OptionSpec& spec : specs) {
        auto& owners = owners_[spec.name];
        if (std::find(owners.begin(), owners.end(), owner) == owners.end()) owners.push_back(owner);
        if (added_.count(spec.name)) continue;
        CLI::Option* option = addOption(command_, spec, values_);
        const std::string shown = defaultText(spec);
        if (!shown.empty()) option->default_str(shown);
        added_[spec.name] = option;
    }
}

void DeclaredOptions::refuseUnused(const std::vector<OptionSpec>& used, const std::string& chosen) const {
    for (const auto& entry : added_) {
        const std::string& name = entry.first;
        if (entry.second->count() == 0) continue;
        const bool read = std::any_of(used.begin(), used.end(), [&](const OptionSpec& s) { return s.name == name; });
        if (read) continue;
        throw InputError(name + " is not used by " + chosen + "; it is an option of " + listed(owners_.at(name)));
    }
}

}  // namespace rad
