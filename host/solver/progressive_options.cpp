#include "solver/progressive_options.h"

namespace rad {

const OptionSpec kRaysOption = OptionSpec::count(
    "--rays",
    "rays for a shot of all the emitted power; each shot casts rays in proportion to its power (where the scene "
    "returns more than 3/4 of the light shot at it, a shot of G / 4 times the emitted power, G = 1 / (1 - the share "
    "returned): see --no-overshoot); the sky's or environment map's direct light takes rays in proportion",
    16'000'000, 1, 1099511627776.0);
const OptionSpec kNoOvershootOption = OptionSpec::flag(
    "--no-overshoot",
    "where the scene returns more than 3/4 of the light shot at it (reflectance near 1), do not overshoot (shoot "
    "the light a patch is expected to receive along with what it has) nor let rays carry more power; such solves "
    "then take up to 1 / (1 - reflectance) times as long (for comparisons)");
const OptionSpec kMinRaysOption = OptionSpec::count(
    "--min-rays", "rays of the weakest shots (a cluster of small patches shares them out by power)", 128, 1,
    1073741824.0);
const OptionSpec kNoClustersOption = OptionSpec::flag(
    "--no-clusters",
    "shoot every patch on its own, however small, each shot with at least --min-rays rays, instead of in clusters "
    "of the patches smaller than half the patch size (for comparisons: on finely tessellated scenes it costs "
    "several times as many rays for the same result)");
const OptionSpec kNoPoolingOption = OptionSpec::flag(
    "--no-pooling",
    "give every element of a cluster of small patches the light its own rays brought, instead of pooling it with "
    "the cluster's elements whose hits agree within their Poisson noise (unbiased, noisier: for comparisons)");
const OptionSpec kToleranceOption =
    OptionSpec::fraction("--tolerance", "stop when unshot / emitted power falls below this", 1e-3, 0.0, 1.0);
const OptionSpec kMaxShotsOption =
    OptionSpec::count("--max-shots", "stop after this many shots (0: no limit)", 0, 0, 1e15);
const OptionSpec kTimeLimitOption =
    OptionSpec::fraction("--time-limit", "stop after this many seconds of solving (0: no limit)", 0.0, 0.0, 1e9);
const OptionSpec kCheckpointOption =
    OptionSpec::text("--checkpoint", "save the solver's state to this file now and then, and when the solve stops");
const OptionSpec kCheckpointEveryOption =
    OptionSpec::positive("--checkpoint-every", "seconds between checkpoints", 60.0);
const OptionSpec kResumeOption = OptionSpec::text(
    "--resume", "continue from a checkpoint of the same scene and options (same seed: bitwise the same result)");
const OptionSpec kElementSizeOption = OptionSpec::positive(
    "--element-size", "receivers finer than shooters: longest element edge in metres (default: one element per patch)");
const OptionSpec kAdaptiveOption = OptionSpec::flag(
    "--adaptive", "split elements where the light bends across them (shadow edges, penumbrae) before the final solve");
const OptionSpec kRefineThresholdOption = OptionSpec::positive(
    "--refine-threshold",
    "adaptive: split elements where linear shading misses the light by more than this fraction of its level", 0.05);
const OptionSpec kMinElementSizeOption =
    OptionSpec::positive("--min-element-size", "adaptive: never split below this edge (default: patch size / 16)");
const OptionSpec kMaxElementsOption =
    OptionSpec::count("--max-elements", "adaptive: stop splitting at this many elements", 4'000'000, 1, 1e12);
const OptionSpec kRefinePassesOption =
    OptionSpec::count("--refine-passes",
                      "adaptive: at most this many passes by direct light (then one by a provisional solve)", 4, 1, 64);

}  // namespace rad
