#pragma once
// The options of progressive refinement, declared once (util/options.h): the device strategy
// reads them all, the matrix strategy's progressive solver --tolerance, and the report shows
// the values of the first five.

#include "util/options.h"

namespace rad {

extern const OptionSpec kRaysOption;             // --rays: rays for a shot of all the emitted power
extern const OptionSpec kNoOvershootOption;      // --no-overshoot: never overshoot nor scale rays' power
extern const OptionSpec kMinRaysOption;          // --min-rays
extern const OptionSpec kNoClustersOption;       // --no-clusters: every patch shoots on its own
extern const OptionSpec kNoPoolingOption;       // --no-pooling: clusters' elements keep their own hits
extern const OptionSpec kToleranceOption;        // --tolerance: unshot / emitted power to stop at
extern const OptionSpec kMaxShotsOption;         // --max-shots
extern const OptionSpec kTimeLimitOption;        // --time-limit
extern const OptionSpec kCheckpointOption;       // --checkpoint FILE
extern const OptionSpec kCheckpointEveryOption;  // --checkpoint-every S
extern const OptionSpec kResumeOption;           // --resume FILE
extern const OptionSpec kElementSizeOption;      // --element-size L: receivers finer than shooters
extern const OptionSpec kAdaptiveOption;         // --adaptive
extern const OptionSpec kRefineThresholdOption;  // --refine-threshold
extern const OptionSpec kMinElementSizeOption;   // --min-element-size
extern const OptionSpec kMaxElementsOption;      // --max-elements
extern const OptionSpec kRefinePassesOption;     // --refine-passes

}  // namespace rad
