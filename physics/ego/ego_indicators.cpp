// The reference driver's indicators (ego_indicators.hpp).
#include "physics/ego/ego_indicators.hpp"

namespace scenfuzz {

VehicleSignals overtake_indicator(const OvertakePlan& plan, double progress) {
  if (!plan.active && !plan.indicating) return 0;
  const VehicleSignals out =
      plan.offset >= 0 ? vehicle_signal::left_indicator : vehicle_signal::right_indicator;
  const VehicleSignals back =
      plan.offset >= 0 ? vehicle_signal::right_indicator : vehicle_signal::left_indicator;
  if (!plan.active) return out;  // indicating before it pulls out
  if (progress >= plan.back_begin) return progress < plan.back_end ? back : 0;
  if (plan.back_indicating_since >= 0) return back;  // before moving back
  return progress < plan.out_end ? out : 0;
}

EgoIndicators::EgoIndicators(const RoadMap& map, const RouteTracker& route,
                             const IndicationNotice& notice)
    : stretches_(route_indications(map, route.segments(), route.lane_changes())), notice_(notice) {}

VehicleSignals EgoIndicators::look(double progress, double speed, const OvertakePlan& plan) {
  const VehicleSignals route = indicator_at(stretches_, progress, speed, cursor_, notice_);
  const VehicleSignals overtake = overtake_indicator(plan, progress);
  return overtake != 0 ? overtake : route;
}

}  // namespace scenfuzz
