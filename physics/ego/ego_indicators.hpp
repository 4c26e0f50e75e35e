// The reference driver's indicators: before and through the lane changes and junction turns of
// its route (route_indications.hpp), and through the sideways moves of an overtaking manoeuvre
// (overtaking.hpp): out towards the passing lane, back towards its own.
#pragma once

#include <vector>

#include "physics/actors/vehicle_signals.hpp"
#include "physics/ego/overtaking.hpp"
#include "physics/ego/route_indications.hpp"
#include "physics/ego/route_tracker.hpp"

namespace scenfuzz {

// The indicator an overtaking plan asks for at path arc length `progress`: towards the passing
// lane while indicating before it pulls out and while moving out, back while moving back, none
// while level with what it passes.
VehicleSignals overtake_indicator(const OvertakePlan& plan, double progress);

class EgoIndicators {
 public:
  EgoIndicators(const RoadMap& map, const RouteTracker& route, const IndicationNotice& notice = {});

  // At the route tracker's progress now, at `speed`, with the driver's overtaking plan; the
  // progress must not go backwards between calls.
  VehicleSignals at(double progress, double speed, const OvertakePlan& plan) {
    // Inline for the common case, neither overtaking nor anything left to indicate.
    if (!plan.active && !plan.indicating && cursor_.next >= stretches_.size()) return 0;
    return look(progress, speed, plan);
  }

  const std::vector<IndicationStretch>& stretches() const { return stretches_; }

 private:
  VehicleSignals look(double progress, double speed, const OvertakePlan& plan);

  std::vector<IndicationStretch> stretches_;
  IndicationCursor cursor_;
  IndicationNotice notice_;
};

}  // namespace scenfuzz
