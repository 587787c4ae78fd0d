#pragma once
// The command line, made from declared options (util/options.h) and nothing else: every option of
// every command is an OptionSpec with its help, kind, default and checks, added to its command
// by DeclaredOptions. A command's own options are bound to the fields of its arguments, which
// start at the declared defaults; the options that methods, solvers and strategies declare are
// added once, whoever declares them, and go into an OptionValues. After parsing, such an option
// that the chosen method, solver or strategy does not read is refused with a message naming who
// would read it, instead of being silently ignored.

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

class DeclaredOptions {
public:
    // `values` receives the options added by add(); none where a command has no such options.
    explicit DeclaredOptions(CLI::App* command, OptionValues* values = nullptr) : command_(command), values_(values) {}

    // The command's own option, stored in `field` as it is parsed; the field is set to the
    // spec's default now.
    void bind(const OptionSpec& spec, bool& field);
    void bind(const OptionSpec& spec, std::string& field);
    void bind(const OptionSpec& spec, glm::vec3& field);
    void bind(const OptionSpec& spec, double& field);
    void bind(const OptionSpec& spec, int& field);
    void bind(const OptionSpec& spec, std::uint32_t& field);
    void bind(const OptionSpec& spec, std::uint64_t& field);
    // A positional Text argument given one or more times (SCENE...).
    void bind(const OptionSpec& spec, std::vector<std::string>& field);

    // Adds the specs not added yet, into the values; `owner` says who reads them ("--method
    // hemicube").
    void add(const std::vector<OptionSpec>& specs, const std::string& owner);

    // Throws InputError for an option the user gave that add() added and that is not in `used`
    // (the first by name): "--X is not used by <chosen>; it is an option of <owners>".
    void refuseUnused(const std::vector<OptionSpec>& used, const std::string& chosen) const;

private:
    void bindNumber(const OptionSpec& spec, std::function<void(double)> store);
    CLI::Option* make(const OptionSpec& spec, std::function<void(double)> number,
                      std::function<void(const std::string&)> text);

    CLI::App* command_;
    OptionValues* values_;
    std::map<std::string, CLI::Option*> added_;                // every option, by name
    std::map<std::string, std::vector<std::string>> owners_;  // those add() added, and who reads them
};

// The files every command reads its scene from (one glTF file, or OBJ, STL and PLY files) and
// the mesh files' length unit: scene/scene_files.h.
struct SceneFileArgs {
    std::vector<std::string> files;
    std::string unit = "m";
    std::string name() const;  // the files, comma-separated, for messages and the report
};

void addSceneFileOptions(DeclaredOptions& options, SceneFileArgs& args);

// --threads N on a command: the CPU device's threads (PoCL's POCL_MAX_PTHREAD_COUNT, which it
// reads when the first OpenCL call finds its devices). 0, the default: what the environment says,
// else every core. Results are the same bits at any count.
void addThreadsOption(CLI::App* command, std::uint32_t& threads);
// Sets it for this process; call before any OpenCL call. Other devices ignore it.
void applyThreads(std::uint32_t threads);
Scene loadScene(const SceneFileArgs& args);

// What solve and viewfactors take to mesh a scene: the scene, the patch size, the seed of the
// sample sequences, the device and the patch limit. (pathtrace meshes whole faces.)
struct SceneInputArgs {
    SceneFileArgs scene;
    double patchSize = 0.0;  // 0: derived from the scene
    std::uint32_t seed = 0;
    std::string device;
    std::uint64_t maxPatches = 0;
};

void addSceneInputOptions(DeclaredOptions& options, SceneInputArgs& args);

// The device a rank uses: --device may list one per rank, separated by commas ("0,1"); rank r
// takes entry r mod the list's length, so one process (rank 0) takes the first.
std::string deviceForRank(const std::string& devices, int rank);

// What solve and pathtrace add to the scene's light: light from outside the scene, which glTF
// cannot say (--sky R,G,B, or --environment FILE.exr with --environment-strength S), and
// materials from a properties file (--properties FILE.csv: scene/property_materials.h), which
// mesh files cannot say.
struct LightingArgs {
    glm::vec3 sky{0.0f};  // uniform radiance, W / m^2 / sr per channel
    std::string environment;
    double environmentStrength = 0.0;
    std::string properties;
    bool solidGlass = false;  // --solid-glass (scene/closed_glass.h)
};

void addLightingOptions(DeclaredOptions& options, LightingArgs& args);
void applyLighting(const LightingArgs& args, Scene& scene);

// The refusal for a scene that nothing lights, naming every way light can enter it.
[[noreturn]] void refuseUnlitScene(const std::string& path, const std::string& consequence);

}  // namespace rad
