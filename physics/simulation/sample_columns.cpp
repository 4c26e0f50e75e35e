// Recording the trace's samples a block of steps at a time (see sample_columns.hpp).
#include "physics/simulation/sample_columns.hpp"

#include <limits>

#include "lang/demand.hpp"

namespace scenfuzz {
namespace {

// Every per-sample column the recorder fills.
template <typename Visit>
void for_each_sample_column(Trace& trace, Visit visit) {
  for (TraceActor& actor : trace.actors) {
    visit(actor.x), visit(actor.y), visit(actor.heading), visit(actor.speed);
    visit(actor.acceleration), visit(actor.yaw_rate), visit(actor.lane), visit(actor.s);
    visit(actor.reversing);
  }
  for (PerceivedActor& perceived : trace.perceived) {
    visit(perceived.detected), visit(perceived.x), visit(perceived.y);
    visit(perceived.heading), visit(perceived.speed), visit(perceived.reversing);
  }
}

}  // namespace

SampleRecorder::SampleRecorder(Trace& trace, std::size_t samples)
    : trace_(trace), actors_(trace.actors.size()), block_(kBlock * trace.actors.size()) {
  SCENFUZZ_DEMAND(trace.perceived.size() + 1 == actors_ || trace.perceived.empty());
  trace.time.reserve(samples);
  for_each_sample_column(trace, [&](auto& column) { column.reserve(samples); });
  for (TraceActor& actor : trace.actors)
    if (actor.kind == TraceActorKind::ego || actor.kind == TraceActorKind::vehicle)
      actor.signals.reserve(samples);
  for (TraceLight& light : trace.lights) light.colour.reserve(samples);
}

void SampleRecorder::sample(std::size_t k, const KinematicState& state, LaneFix lane) {
  Row& row = block_[rows_ * actors_ + k];
  row.state = state;
  row.lane = lane;
}

void SampleRecorder::perceived(std::size_t k, const WorldObject* seen) {
  Row& row = block_[rows_ * actors_ + k];
  row.detected = seen != nullptr;
  if (seen) row.seen = *seen;
}

void SampleRecorder::end_step() {
  if (++rows_ == kBlock) flush();
}

void SampleRecorder::flush() {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < actors_; ++k) {
    TraceActor& actor = trace_.actors[k];
    SCENFUZZ_DEMAND(actor.x.size() == first_);
    for (std::size_t r = 0; r < rows_; ++r) {
      const Row& row = block_[r * actors_ + k];
      actor.x.push_back(row.state.x);
      actor.y.push_back(row.state.y);
      actor.heading.push_back(row.state.heading);
      actor.speed.push_back(row.state.speed);
      actor.acceleration.push_back(row.state.acceleration);
      actor.yaw_rate.push_back(row.state.yaw_rate);
      actor.lane.push_back(row.lane.lane);
      actor.s.push_back(row.lane.s);
      actor.reversing.push_back(row.state.reversing ? 1 : 0);
    }
    if (k == 0 || trace_.perceived.empty()) continue;
    PerceivedActor& column = trace_.perceived[k - 1];
    for (std::size_t r = 0; r < rows_; ++r) {
      const Row& row = block_[r * actors_ + k];
      column.detected.push_back(row.detected ? 1 : 0);
      column.x.push_back(row.detected ? row.seen.x : nan);
      column.y.push_back(row.detected ? row.seen.y : nan);
      column.heading.push_back(row.detected ? row.seen.heading : nan);
      column.speed.push_back(row.detected ? row.seen.speed : nan);
      column.reversing.push_back(row.detected && row.seen.reversing ? 1 : 0);
    }
  }
  first_ += rows_;
  rows_ = 0;
}

void SampleRecorder::finish() {
  flush();
  SCENFUZZ_DEMAND(first_ == trace_.time.size());
}

}  // namespace scenfuzz
