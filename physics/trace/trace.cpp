// Trace look-ups and the names its enumerations are written with in exports and messages.
#include "physics/trace/trace.hpp"

namespace scenfuzz {

std::optional<ActorId> Trace::find_actor(const std::string& name) const {
  for (std::size_t i = 0; i < actors.size(); ++i)
    if (actors[i].name == name) return static_cast<ActorId>(i);
  return std::nullopt;
}

std::string_view trace_actor_kind_name(TraceActorKind kind) {
  switch (kind) {
    case TraceActorKind::ego: return "ego";
    case TraceActorKind::vehicle: return "vehicle";
    case TraceActorKind::pedestrian: return "pedestrian";
    case TraceActorKind::obstacle: return "obstacle";
  }
  return "unknown";
}

std::string_view end_reason_name(EndReason reason) {
  switch (reason) {
    case EndReason::duration: return "duration";
    case EndReason::target_reached: return "target_reached";
    case EndReason::collision: return "collision";
    case EndReason::ego_failure: return "ego_failure";
    case EndReason::end_condition: return "end_condition";
  }
  return "unknown";
}

std::string_view ego_failure_kind_name(EgoFailureKind kind) {
  switch (kind) {
    case EgoFailureKind::crash: return "ego_crash";
    case EgoFailureKind::hang: return "ego_hang";
    case EgoFailureKind::error: return "ego_error";
  }
  return "ego_error";
}

std::string_view signal_colour_name(SignalColour colour) {
  switch (colour) {
    case SignalColour::red: return "red";
    case SignalColour::yellow: return "yellow";
    case SignalColour::green: return "green";
  }
  return "unknown";
}

}  // namespace scenfuzz
