#include "lang/parameter.hpp"

namespace scenfuzz {

std::string_view kind_name(ParameterKind kind) {
  switch (kind) {
    case ParameterKind::continuous: return "continuous";
    case ParameterKind::angle: return "angle";
    case ParameterKind::discrete: return "discrete";
  }
  return "continuous";
}

}  // namespace scenfuzz
