#pragma once
// Command-line helpers the subcommands share: whole numbers that may be written 16e6, positive
// numbers with a short message, and the command line made from the options that methods,
// solvers and strategies declare
// (util/options.h): each declared option is added to a subcommand once, whoever declares it,
// with its help and checks; what the user gives goes into an OptionValues. After parsing, an
// option the chosen method, solver or strategy does not read is refused with a message naming
// who would read it, instead of being silently ignored.

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.h"
#include "util/options.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace rad {

// What solve and viewfactors take to mesh a scene: the scene, the patch size, the seed of the
// sample sequences, the device and the patch limit. (pathtrace meshes whole faces.)
struct SceneInputArgs {
    std::string scene;
    double patchSize = 0.0;  // 0: derived from the scene
    std::uint32_t seed = 1;
    std::string device;
    std::uint64_t maxPatches = 10'000'000;
};

void addSceneInputOptions(CLI::App* command, SceneInputArgs& args);

// The device a rank uses: --device may list one per rank, separated by commas ("0,1"); rank r
// takes entry r mod the list's length, so one process (rank 0) takes the first.
std::string deviceForRank(const std::string& devices, int rank);

// Light from outside the scene, which glTF cannot say (solve and pathtrace): --sky R,G,B, or
// --environment FILE.exr with --environment-strength S.
struct LightingArgs {
    glm::vec3 sky{0.0f};  // uniform radiance, W / m^2 / sr per channel
    std::string environment;
    double environmentStrength = 1.0;
};

void addLightingOptions(CLI::App* command, LightingArgs& args);
void applyLighting(const LightingArgs& args, Scene& scene);

// The refusal for a scene that nothing lights, naming every way light can enter it.
[[noreturn]] void refuseUnlitScene(const std::string& path, const std::string& consequence);

// An option taking a whole number in [min, max], written 16000000, 16e6 or 1.6e7.
CLI::Option* addWholeNumber(CLI::App* app, const std::string& name, std::function<void(double)> store,
                            const std::string& help, double min, double max);
// An option taking a positive finite number.
CLI::Option* addPositiveNumber(CLI::App* app, const std::string& name, std::function<void(double)> store,
                               const std::string& help);

class DeclaredOptions {
public:
    DeclaredOptions(CLI::App* command, OptionValues& values) : command_(command), values_(values) {}

    // Adds the specs not added yet; `owner` says who reads them ("--method hemicube").
    void add(const std::vector<OptionSpec>& specs, const std::string& owner);

    // Throws InputError for an option the user gave that is not in `used` (the first by name):
    // "--X is not used by <chosen>; it is an option of <owners>".
    void refuseUnused(const std::vector<OptionSpec>& used, const std::string& chosen) const;

private:
    CLI::App* command_;
    OptionValues& values_;
    std::map<std::string, CLI::Option*> added_;
    std::map<std::string, std::vector<std::string>> owners_;
};

}  // namespace rad
