// A lane map from road outlines, as CH-Scenario road networks give them: each road is a left
// boundary, a centre line and a right boundary, polylines in the map plane (ENU metres) whose point
// order is the driving direction. The rules, which docs/ch-scenario.md quotes:
//
//  1. Each road has two halves. The right half (between the centre line and the right boundary)
//     carries lanes driving in the centre line's point order; the left half (between the centre
//     line and the left boundary) carries lanes driving against it (right-hand traffic).
//  2. A half's width at a point of the centre line is the distance from that point to the
//     nearest point of the boundary polyline on that side. The centre line is sampled at its
//     vertices and at most every 5 m between them (boundaries may have more points than the
//     centre line). A half whose widths are all below 1.0 m has no lanes (so a road whose left
//     boundary lies on its centre line is one-way). A road with no lane on either half is an
//     error.
//  3. A half of mean width W (mean over the centre line's arc length) has
//     n = max(1, round(W / 3.5)) lanes, each 1/n of the half's width at every sample. Lane k
//     (k = 0 next to the centre line, counting outwards) has its centre at offset
//     (k + 0.5) w(s) / n from the centre line towards its boundary, and half-widths of w(s) / 2n
//     on each side, sampled at the lane's own arc length. Offsets run along the vertex normal
//     (the average of the adjacent segments' normals), so a bend keeps its width reasonably.
//     Each lane's centre line runs in its driving direction (the left half's are reversed).
//  4. Lane ids: <road>_f<k> for lanes in the point order (forward), <road>_b<k> for lanes
//     against it, k counted from the centre line: narrow_road_f0 is the forward lane next to the
//     centre line and narrow_road_f<n-1> the kerb lane. A road that meets a junction (rule 9) is
//     cut there: each lane's pieces are <road>_f<k>_<i>, i = 1, 2, ... in its driving direction,
//     and <road>_f<k> names the chain of its pieces (MapDescription::lane_chains), so a position
//     written on it finds its piece by the arc length along the whole lane.
//  5. Neighbours: f<k>'s left forward neighbour is f<k-1>, its right forward neighbour f<k+1>;
//     f0's left reverse neighbour is b0 and b0's is f0; the same for the b lanes. Boundaries
//     between lanes of one direction are dotted white, the centre line between f0 and b0 is dotted
//     yellow (a two-lane rural road where overtaking is allowed), the outer edges (and the centre
//     line of a one-way road) are curbs. Each lane carries its boundary polylines for drawing.
//  6. Connections: a lane whose last point lies within 1.5 m of another lane's first point (of
//     any road, the same one included) and whose end heading differs from that lane's start
//     heading by less than 60 degrees gets it as successor, and the other gets it as predecessor.
//     The pieces of a cut lane and the turns of a junction connect so too.
//  7. Errors (MapError, the message starting with "road 'NAME': "): fewer than two points in any
//     polyline; a centre line of zero length; a coordinate that is not finite; a boundary that
//     crosses to the other side of the centre line (a right-boundary point lying more than
//     0.01 m left of the centre line, judged at the nearest centre-line point, or vice versa),
//     naming the point; two roads with the same name; a road with an empty name. An empty road
//     list is an error too (its message starts with "map 'NAME': ").
//  8. Every lane of a road has the road's speed limit. The description is named as given, its
//     source is "CH-Scenario road network", its default lane width 3.5 m, and it has no
//     projection.
//  9. Junctions (outline_junction_sites.hpp has the geometry): two roads whose centre lines
//     cross, or where one's, carried straight on past its end (or back before its start) for
//     the other's widest half and 1.5 m more, reaches the other's, meet in a junction named
//     junction_<road>_<road> (in road order). Roads meeting end to start within 60 degrees are
//     not one: one continues into the other (rule 6). Along each road the junction reaches
//     W_other / sin(theta) + W_own * |cot(theta)| + 6 m either side of the meeting point (W
//     the wider half there, theta the angle between the roads): the other road's width across
//     it, its own width's slant and room to turn round the corners. A road crossing the junction
//     keeps its stretch inside as pieces of the junction, straight on; a road ending (starting)
//     inside loses it. Where each road leaves the junction it is an arm; from every arm's lane
//     next to the centre line a connector turns left into every arm lying to the left (more than
//     30 degrees from straight on and from straight back), into that arm's lane next to the
//     centre line, and from the kerb lane a connector turns right into the kerb lane of every
//     arm to the right (outline_connectors.hpp: <in lane>_to_<out lane>, a Bezier curve tangent
//     to both). The junction's outline is the convex hull of the road edges where the arms
//     begin. Roads meeting at less than 30 degrees, a road too short to leave a junction (it
//     lies within the junction's reach both ways) and junctions overlapping along a road are
//     errors naming the roads. Without a traffic light (rule 10) a junction has no signs or
//     signals: who goes first is the simulation's rule for junctions without them
//     (docs/simulation.md, "Junctions: who goes first").
// 10. Traffic lights (outline_signals.hpp): each OutlineSignal controls the junction whose
//     meeting point is nearest its point. Each of the junction's two roads gets a light,
//     <signal>_<road>, over its lanes coming in, its stop lines across their ends; the roads take
//     turns, 25 s green, 3 s yellow and 2 s all red each (the built-in crossroads' default plan),
//     the signal's road (or, when the junction is not on it, the junction's first road) showing
//     the signal's colour at the start of that phase and the other road the rest of the cycle.
//     A signal on a network without junctions, or two on one junction, is an error naming it.
#pragma once

#include <string>
#include <vector>

#include "physics/map/map_description.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz {

// One road of the network, its points evaluated (the IR's RoadOutline holds Values).
struct RoadOutlineGeometry {
  std::string name;
  std::vector<MapPoint> left_boundary, centre_line, right_boundary;
  double speed_limit = 0;  // m/s on every lane of the road; 0: none
};

// A traffic light on the network (rule 10).
struct OutlineSignal {
  std::string name;
  MapPoint at;
  std::string road;  // whose lights show `colour` at the start
  SignalColour colour = SignalColour::green;
};

// The lanes of `roads` by the rules above, with `signals`; build_road_map makes it a RoadMap.
// Throws MapError naming the road (and the point) for bad geometry, or the signal.
MapDescription describe_outline_map(std::string name, const std::vector<RoadOutlineGeometry>& roads,
                                    const std::vector<OutlineSignal>& signals = {});

}  // namespace scenfuzz
