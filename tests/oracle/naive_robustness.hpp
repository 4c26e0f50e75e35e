// A reference implementation of the STL robustness semantics (DESIGN.md "Semantics", RTAMT's
// discrete-time conventions), written straight from the definitions with quadratic loops and
// sharing no code with oracle/robustness.cpp, so that tests can check the linear-time engine
// against it.
#pragma once

#include <vector>

#include "lang/spec.hpp"
#include "oracle/robustness.hpp"

namespace scenfuzz::test {

// The robustness of `formula` at every sample of `source.time`, by the definitions: a window
// operator looks at every sample of the trace, until at every pair of samples. Throws OracleError
// where the engine must (an unknown or malformed leaf, a value that is not a finite number).
std::vector<double> naive_robustness(const Formula& formula, const SignalSource& source);

}  // namespace scenfuzz::test
