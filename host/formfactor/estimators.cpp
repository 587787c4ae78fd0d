#include "formfactor/estimator.h"

#include "util/error.h"

namespace rad {

const std::vector<FormFactorMethod>& formFactorMethods() {
    // One line per method; the first is the default.
    static const std::vector<FormFactorMethod> methods = {
        shootMethod(),
        hemicubeMethod(),
        gatherMethod(),
    };
    return methods;
}

const FormFactorMethod& formFactorMethod(const std::string& name) {
    std::string choices;
    for (const FormFactorMethod& m : formFactorMethods()) {
        if (m.name == name) return m;
        choices += (choices.empty() ? "" : ", ") + m.name;
    }
    throw InputError("--method " + name + ": use one of " + choices);
}

}  // namespace rad
