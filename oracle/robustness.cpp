#include "oracle/robustness.hpp"
