// The trace's per-sample columns as the simulation records them: sized for the whole run before
// its first step and written by index, then cut to the samples taken when it ends. A push_back's
// capacity test and bookkeeping, on 15 columns per actor and step, cost more than the writes.
#pragma once

#include <cstddef>

#include "physics/actors/kinematics.hpp"
#include "physics/ego/perception.hpp"
#include "physics/simulation/lane_tracker.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// Sizes every actor's and perceived actor's sample columns for `samples` samples, and reserves
// the others (time, signals, lights' colours) as many.
void size_sample_columns(Trace& trace, std::size_t samples);

// Sample i of the actor, and of what perception reports of it (null: not detected).
void write_sample(TraceActor& actor, std::size_t i, const KinematicState& state, LaneFix lane);
void write_perceived(PerceivedActor& column, std::size_t i, const WorldObject* seen);

// Cuts the sized columns to the samples taken (trace.time's).
void trim_sample_columns(Trace& trace);

}  // namespace scenfuzz
