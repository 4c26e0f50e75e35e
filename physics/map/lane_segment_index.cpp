// The lane segment R-tree (Boost.Geometry, packed at construction with the STR algorithm).
#include "physics/map/lane_segment_index.hpp"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <utility>

#include "physics/map/road_map.hpp"

namespace scenfuzz {

namespace geometry = boost::geometry;
namespace index = boost::geometry::index;

using IndexPoint = geometry::model::point<double, 2, geometry::cs::cartesian>;
using IndexSegment = geometry::model::segment<IndexPoint>;
using IndexBox = geometry::model::box<IndexPoint>;
using IndexValue = std::pair<IndexSegment, LaneSegmentReference>;

struct LaneSegmentIndex::Tree {
  index::rtree<IndexValue, index::rstar<16>> rtree;
};

namespace {

IndexPoint to_index_point(MapPoint point) { return {point.x, point.y}; }

}  // namespace

LaneSegmentIndex::LaneSegmentIndex(const std::vector<Lane>& lanes) {
  std::vector<IndexValue> values;
  for (std::uint32_t lane = 0; lane < lanes.size(); ++lane) {
    const std::vector<MapPoint>& points = lanes[lane].centre_line.points();
    for (std::uint32_t segment = 0; segment + 1 < points.size(); ++segment) {
      values.emplace_back(
          IndexSegment{to_index_point(points[segment]), to_index_point(points[segment + 1])},
          LaneSegmentReference{lane, segment});
    }
  }
  // The range constructor packs the tree (STR bulk loading): faster queries than inserting.
  tree_ = std::make_unique<Tree>(Tree{{values.begin(), values.end()}});
}

LaneSegmentIndex::~LaneSegmentIndex() = default;

bool LaneSegmentIndex::nearest(MapPoint point, LaneSegmentReference& result) const {
  auto found = tree_->rtree.qbegin(index::nearest(to_index_point(point), 1));
  if (found == tree_->rtree.qend()) return false;
  result = found->second;
  return true;
}

void LaneSegmentIndex::visit_nearest(
    MapPoint point, const std::function<bool(const LaneSegmentReference&)>& visit) const {
  // The query iterator is incremental: asking for every value costs only what is visited.
  auto query = index::nearest(to_index_point(point), static_cast<unsigned>(tree_->rtree.size()));
  for (auto it = tree_->rtree.qbegin(query); it != tree_->rtree.qend(); ++it) {
    if (!visit(it->second)) return;
  }
}

std::vector<LaneSegmentReference> LaneSegmentIndex::segments_in_box(MapPoint min,
                                                                    MapPoint max) const {
  std::vector<LaneSegmentReference> result;
  IndexBox box{to_index_point(min), to_index_point(max)};
  for (auto it = tree_->rtree.qbegin(index::intersects(box)); it != tree_->rtree.qend(); ++it)
    result.push_back(it->second);
  return result;
}

}  // namespace scenfuzz
