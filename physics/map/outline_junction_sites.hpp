// Internal to outline_map.cpp: where the roads of an outline network meet, each meeting a
// junction (outline_map.hpp, rule 9). Two roads meet where their centre lines cross, or where
// one's centre line, carried straight on past its end (or back before its start) for the other
// road's widest half width and 1.5 m more, reaches the other's: a road that ends at (or starts
// from) another's edge. Each road's stretch inside the junction reaches the other road's width
// across it, its own width's slant and a margin for turning round the corners:
//   d = W_other / sin(theta) + W_own * |cot(theta)| + 6 m
// either side of the meeting point, W the wider half at that point, theta the angle between
// the roads. Roads meeting end to start within 60 degrees are not a junction: one continues into
// the other (rule 6).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "physics/map/map_point.hpp"
#include "physics/map/outline_half_road.hpp"
#include "physics/map/polyline.hpp"

namespace scenfuzz::outline {

// What the junction finder needs of a road: its name, centre line, samples and the widths of
// its halves at them.
struct RoadShape {
  std::string name;
  Polyline centre;
  std::vector<CentreSample> samples;
  std::vector<double> right_widths, left_widths;
};

// How a road takes part in a junction: it crosses it, or ends or starts inside it.
enum class LegKind { through, ends, starts };

// One road's part in a junction: the stretch [begin, end] of its centre line inside it (to the
// road's end for `ends`, from its start for `starts`).
struct JunctionLeg {
  std::size_t road = 0;
  LegKind kind = LegKind::through;
  double begin = 0, end = 0;
};

struct JunctionSite {
  std::string id;  // junction_<road>_<road>, a number added for a second meeting of the two
  MapPoint centre;
  std::array<JunctionLeg, 2> legs;
};

// Every meeting of two roads of `roads`, in road order. Throws MapError naming the roads for
// roads meeting at less than 30 degrees, a road too short to leave a junction, and junctions
// whose stretches on one road overlap.
std::vector<JunctionSite> find_junction_sites(const std::vector<RoadShape>& roads);

}  // namespace scenfuzz::outline
