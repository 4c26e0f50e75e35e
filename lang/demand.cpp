#include "lang/demand.hpp"

#include <cstdio>
#include <cstdlib>

namespace scenfuzz {

void demand_failed(const char* condition, const char* file, int line) {
  std::fprintf(stderr,
               "scenfuzz: internal error: %s:%d: failed: %s\n"
               "This is a bug in scenfuzz; please report it with the command that caused it.\n",
               file, line, condition);
  std::abort();
}

}  // namespace scenfuzz
