// Edits of a level-2 syntax tree that make a concrete WMG SDL scenario smaller while keeping it a
// valid file: what `scenfuzz tmin` tries on a WMG SDL finding before printing it with
// print_level2. Working on the tree rather than the scenario IR keeps everything the IR cannot be
// printed back from (manoeuvre phases as written, road parameters, the WHEN/WHILE/END wording).
// Every edit leaves a tree that prints and parses back; whether it still translates (and still
// fails) is for the caller's predicate to say.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "lang/wmg/syntax.hpp"

namespace scenfuzz::wmg {

// The actors other than the ego (docs/wmg-semantics.md "Actors"), in initialisation order.
std::vector<std::string> other_actors(const Level2File& file);

// Removes the actors `kept` is false for (kept[i] for other_actors(file)[i]) and everything that
// mentions them: an actor placed relative to a removed one goes too (its place is gone), so do
// the phases, WHEN conditions, WHILE constraints and END conditions naming any of them; a
// sequence left without phases, and a WHEN ... DO left without conditions or sequences, go as
// well. Returns the names removed beyond those asked for (the actors placed relative to them).
std::vector<std::string> remove_actors(Level2File& file, const std::vector<bool>& kept);

// A manoeuvre phase as the printer names it: "phase 2 of Cutter".
struct PhaseName {
  std::string actor;
  std::int64_t number = 0;
};

// Every manoeuvre phase of every sequence, in file order.
std::vector<PhaseName> manoeuvre_phases(const Level2File& file);

// Removes the phases `kept` is false for (kept[i] for manoeuvre_phases(file)[i]); the phases left
// in a sequence are numbered 1, 2, ... again, and emptied sequences and SSMS go.
void remove_phases(Level2File& file, const std::vector<bool>& kept);

// The weather components that are not neutral: "wind", "cloudiness", "particulates", "rainfall",
// "snowfall", in that order.
std::vector<std::string> weather_components(const Level2File& file);

// Makes the named components neutral: no wind, particulates or snowfall, no cloud (0 oktas),
// no rain (Light Rain: 0 mm/h, the grammar needs a rainfall line).
void neutral_weather(Level2File& file, const std::vector<std::string>& components);

// Sets the time of day to `seconds` since midnight; false when it was that already.
bool set_time_of_day(Level2File& file, double seconds);

// The written numbers of the file, in a fixed walk order: the scenery's, the dynamic elements'
// (the END conditions apart: they say when the failure is judged), the environment's (the time of
// day apart: seconds do not round to readable times) and the traffic model's. A range counts
// once, by its low end (a concrete finding has none).
std::vector<double> file_numbers(const Level2File& file);
// Sets them back in the same order (a range becomes the lone number).
void set_file_numbers(Level2File& file, const std::vector<double>& numbers);

}  // namespace scenfuzz::wmg
