// The lane segment R-tree (Boost.Geometry, packed at construction with the STR algorithm).
#include "physics/map/lane_segment_index.hpp"

// Boost 1.74 geometry includes a header it itself deprecates; the note is not ours to fix.
#define BOOST_ALLOW_DEPRECATED_HEADERS
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
  index::rtree<IndexValue, index::rstar<8>> rtree;
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
  // Eight values per node measured fastest for nearest queries on san_francisco (16 and 32 are
  // slower, docs/performance.md; fewer than 8 trips GCC 12 -Warray-bounds inside Boost).
  tree_ = std::make_unique<Tree>(Tree{{values.begin(), values.end()}});
}

LaneSegmentIndex::~LaneSegmentIndex() = default;

bool LaneSegmentIndex::nearest(MapPoint point, LaneSegmentReference& result) const {
  IndexValue found;
  if (tree_->rtree.query(index::nearest(to_index_point(point), 1), &found) == 0) return false;
  result = found.second;
  return true;
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
