#include "solver/energy_balance.h"

#include <algorithm>
#include <cmath>

namespace rad {

double EnergyBalance::relativeResidual() const {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        if (emitted[c] > 0.0)
            worst = std::max(worst, std::fabs(emitted[c] - absorbed[c] - escaped[c] - unshot[c]) / emitted[c]);
    return worst;
}

}  // namespace rad
