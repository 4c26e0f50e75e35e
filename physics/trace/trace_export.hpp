// A trace written out for people and tools: CSV (one row per sample and actor, for
// spreadsheets and plotting scripts) and JSON (columnar like Trace, the form saved with a
// finding and reloaded by the oracle).
#pragma once

#include <span>
#include <string>

#include "physics/trace/trace.hpp"

namespace scenfuzz {

// Header row, then one row per (sample, actor), samples in time order and actors in id order:
//   time,actor,kind,x,y,heading,speed,acceleration,yaw_rate,lane,s,reversing,
//   perceived_detected,perceived_x,perceived_y,perceived_heading,perceived_speed,
//   perceived_reversing,signals
// `reversing` is 1 where the actor moved backwards (its speed against its heading), else 0. The
// perceived columns are empty on the ego's rows, and all but perceived_detected (0) are empty
// where the ego did not detect the actor. Lanes print as `lane_ids[lane]` when ids are
// given (the map's lane ids, in LaneIndex order), else as the index; empty off the lanes.
// `signals` names the vehicle signals on (vehicle_signal_names.hpp) joined by '|'
// ("left_indicator|low_beam"), empty when none are.
// An actor has rows only for the samples it is on the map (TraceActor::present_from/until):
// background traffic comes and goes. Numbers are the shortest text that reads back to the same
// double. Text is quoted as RFC 4180 says. Throws std::out_of_range when a lane index has no entry
// in a non-empty `lane_ids`.
std::string trace_csv(const Trace& trace, std::span<const std::string> lane_ids = {});

// {"format": "scenfuzz-trace", "version": 1, "map", "seed", "dt", "end", "time": [...],
//  "actors": [{"name", "kind", "category", "shape", "length", "width", "height",
//              "present": [from, until] (only for an actor not on the map throughout),
//              "samples": {"x": [...], "y", "heading", "speed", "acceleration", "yaw_rate",
//                          "lane", "s", "reversing": [false, ...],
//                          "signals": [bits, ...] (only for an actor showing signals)}}],
//  "perceived": [{"actor", "detected": [true, ...], "x": [...], "y", "heading", "speed",
//                 "reversing"}],
//  "lights": [{"id", "colour": ["red", ...]}],
//  "collisions": [{"time", "first", "second", "point": [x, y], "first_side", "second_side"}],
//  "events": [{"kind", "time", "collision", "message"}]}
// Actors are referred to by id (their index in "actors"). NaN, such as an undetected perceived
// sample, is written as null (and so is an infinity, which reads back as NaN).
std::string trace_json(const Trace& trace);

// Reads what trace_json writes. Throws std::runtime_error naming the offending place
// ("trace JSON: actors[1].samples.speed: ...") for malformed JSON, a missing or mistyped field,
// an unknown name, a column whose length differs from "time", or an actor id out of range.
// "reversing" may be missing (traces written before it existed): nothing reverses then; so may
// "signals" (none shown), and its bit sets must lie within vehicle_signal::all.
Trace trace_from_json(const std::string& text);

}  // namespace scenfuzz
