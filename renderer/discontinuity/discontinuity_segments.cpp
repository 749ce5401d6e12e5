#include "discontinuity/discontinuity_segments.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

namespace radview {

namespace {

int orderIndex(Continuity c) { return int(c) + 1; }  // C-1, C0, C1 -> 0, 1, 2

struct Piece {
  Vec2 a, b;
  Continuity order;
};

// Segments on one line (within the tolerance): the longest one found first defines it.
struct LineFamily {
  Vec2 origin, direction;  // unit direction
  struct Span {
    double t0, t1;
    Continuity order;
  };
  std::vector<Span> spans;
};

double distanceToLine(const Vec2& p, const LineFamily& line) {
  const Vec2 d = p - line.origin;
  return std::abs(d.x * line.direction.y - d.y * line.direction.x);
}

// Collinear segments merged: along each line, the union of the spans, cut where the strongest
// order covering it changes (the strongest wins where events overlap: a D0 contact on the
// same line as an EV wedge stays C-1).
std::vector<Piece> mergeCollinear(std::vector<EventSegment> segments, double tolerance) {
  std::sort(segments.begin(), segments.end(), [](const EventSegment& x, const EventSegment& y) {
    return glm::distance(x.a, x.b) > glm::distance(y.a, y.b);
  });
  std::vector<LineFamily> families;
  for (const EventSegment& s : segments) {
    if (!(glm::distance(s.a, s.b) > tolerance)) continue;
    LineFamily* family = nullptr;
    for (LineFamily& f : families)
      if (distanceToLine(s.a, f) <= tolerance && distanceToLine(s.b, f) <= tolerance) {
        family = &f;
        break;
      }
    if (!family) {
      families.push_back({s.a, glm::normalize(s.b - s.a), {}});
      family = &families.back();
    }
    double t0 = glm::dot(s.a - family->origin, family->direction);
    double t1 = glm::dot(s.b - family->origin, family->direction);
    if (t0 > t1) std::swap(t0, t1);
    family->spans.push_back({t0, t1, s.order});
  }

  std::vector<Piece> pieces;
  for (const LineFamily& f : families) {
    std::vector<double> cuts;
    for (const auto& span : f.spans) {
      cuts.push_back(span.t0);
      cuts.push_back(span.t1);
    }
    std::sort(cuts.begin(), cuts.end());
    std::vector<double> distinct;  // cuts closer than the tolerance are one
    for (double t : cuts)
      if (distinct.empty() || t - distinct.back() > tolerance) distinct.push_back(t);
    bool open = false;
    double start = 0;
    Continuity current = Continuity::C1;
    auto close = [&](double end) {
      if (open) pieces.push_back({f.origin + start * f.direction, f.origin + end * f.direction, current});
      open = false;
    };
    for (size_t k = 0; k + 1 < distinct.size(); ++k) {
      const double middle = 0.5 * (distinct[k] + distinct[k + 1]);
      int strongest = 3;
      for (const auto& span : f.spans)
        if (span.t0 - tolerance <= middle && middle <= span.t1 + tolerance)
          strongest = std::min(strongest, orderIndex(span.order));
      if (strongest == 3) {
        close(distinct[k]);
        continue;
      }
      const Continuity order = Continuity(strongest - 1);
      if (open && order == current) continue;
      close(distinct[k]);
      open = true;
      start = distinct[k];
      current = order;
    }
    if (!distinct.empty()) close(distinct.back());
  }
  return pieces;
}

// Points closer than the tolerance are one: a hash grid of tolerance-sized cells.
class SnappedPoints {
 public:
  explicit SnappedPoints(double tolerance) : tolerance_(tolerance) {}

  // The index of a point within the tolerance of p, or of p added; `exact` adds p whatever
  // lies near (polygon vertices keep their places).
  int insert(const Vec2& p, bool exact = false) {
    const int64_t cx = cell(p.x), cy = cell(p.y);
    if (!exact)
      for (int64_t dx = -1; dx <= 1; ++dx)
        for (int64_t dy = -1; dy <= 1; ++dy) {
          auto it = grid_.find({cx + dx, cy + dy});
          if (it == grid_.end()) continue;
          for (int id : it->second)
            if (glm::distance(points_[id], p) <= tolerance_) return id;
        }
    points_.push_back(p);
    grid_[{cx, cy}].push_back(int(points_.size() - 1));
    return int(points_.size() - 1);
  }
  const std::vector<Vec2>& points() const { return points_; }

 private:
  int64_t cell(double x) const { return int64_t(std::floor(x / tolerance_)); }

  double tolerance_;
  std::vector<Vec2> points_;
  std::map<std::pair<int64_t, int64_t>, std::vector<int>> grid_;
};

// A boundary edge or a merged segment, with the points where it must be split.
struct Line {
  int a, b;
  bool boundary;
  Continuity order;
  std::vector<std::pair<double, int>> splits;  // (parameter, point)
};

// Adds point `id` at p to `line`'s splits when p lies within the tolerance of its interior.
void splitIfOn(Line& line, int id, const Vec2& p, const std::vector<Vec2>& points, double tolerance) {
  if (id == line.a || id == line.b) return;
  const Vec2 a = points[line.a], b = points[line.b];
  if (distanceToSegment(p, a, b) > tolerance) return;
  const double length = glm::distance(a, b);
  const double t = glm::dot(p - a, b - a) / (length * length);
  if (t * length > tolerance && (1 - t) * length > tolerance) line.splits.push_back({t, id});
}

// Puts each piece's end that lies within the tolerance of another piece's interior exactly on
// that piece's line, when that piece is at least as strong (the strongest, then the nearest):
// left where it is, the end would become a split point of the other piece off that piece's
// line, and a C-1 line (an occluder's footprint, whose nodes are split along it) would bend by
// up to the tolerance there. The strongest pieces' ends are placed first, so that the lines
// weaker ends land on have stopped moving.
void endsOntoStrongerLines(std::vector<Piece>& pieces, double tolerance) {
  std::vector<size_t> strongestFirst(pieces.size());
  for (size_t i = 0; i < pieces.size(); ++i) strongestFirst[i] = i;
  std::stable_sort(strongestFirst.begin(), strongestFirst.end(),
                   [&](size_t x, size_t y) { return orderIndex(pieces[x].order) < orderIndex(pieces[y].order); });
  for (size_t i : strongestFirst)
    for (bool atStart : {true, false}) {
      Vec2& end = atStart ? pieces[i].a : pieces[i].b;
      const Vec2 from = atStart ? pieces[i].b : pieces[i].a;
      const Piece* onto = nullptr;
      double nearest = tolerance;
      for (size_t j = 0; j < pieces.size(); ++j) {
        const Piece& other = pieces[j];
        if (j == i || orderIndex(other.order) > orderIndex(pieces[i].order)) continue;
        const double d = distanceToSegment(end, other.a, other.b);
        if (d > tolerance || glm::distance(end, other.a) <= tolerance || glm::distance(end, other.b) <= tolerance)
          continue;
        if (!onto || orderIndex(other.order) < orderIndex(onto->order) || (other.order == onto->order && d < nearest)) {
          onto = &other;
          nearest = d;
        }
      }
      if (onto) end = endOntoLine(from, end, onto->a, onto->b, 2.0 * tolerance);
    }
}

}  // namespace

SegmentArrangement arrangeSegments(const std::vector<Vec2>& outline, const std::vector<EventSegment>& segments,
                                   double tolerance) {
  SegmentArrangement result;
  std::vector<Piece> pieces = mergeCollinear(segments, tolerance);
  // A piece along a boundary edge (closer than the tolerance) would leave a strip of slivers.
  auto alongBoundary = [&](const Piece& piece) {
    for (size_t i = 0; i < outline.size(); ++i) {
      const Vec2 &a = outline[i], &b = outline[(i + 1) % outline.size()];
      if (distanceToSegment(piece.a, a, b) <= tolerance && distanceToSegment(piece.b, a, b) <= tolerance) return true;
    }
    return false;
  };
  pieces.erase(std::remove_if(pieces.begin(), pieces.end(), alongBoundary), pieces.end());
  if (pieces.size() > kMaxSegmentsPerPolygon) {
    std::sort(pieces.begin(), pieces.end(), [](const Piece& x, const Piece& y) {
      if (x.order != y.order) return int(x.order) < int(y.order);
      return glm::distance(x.a, x.b) > glm::distance(y.a, y.b);
    });
    result.dropped = pieces.size() - kMaxSegmentsPerPolygon;
    pieces.resize(kMaxSegmentsPerPolygon);
  }
  for (const Piece& p : pieces) ++result.mergedSegments[orderIndex(p.order)];
  endsOntoStrongerLines(pieces, tolerance);

  SnappedPoints snapped(tolerance);
  for (const Vec2& p : outline) result.outlinePoint.push_back(snapped.insert(p, true));
  std::vector<Line> lines;
  for (size_t i = 0; i < outline.size(); ++i) {
    const int a = result.outlinePoint[i], b = result.outlinePoint[(i + 1) % outline.size()];
    if (a != b) lines.push_back({a, b, true, Continuity::C1, {}});
  }
  const size_t boundaryLines = lines.size();
  for (const Piece& p : pieces) {
    const int a = snapped.insert(p.a), b = snapped.insert(p.b);
    if (a != b) lines.push_back({a, b, false, p.order, {}});
  }

  // Every pair but boundary-boundary (the outline is simple): endpoints of one on the other,
  // and proper crossings, made shared points.
  for (size_t i = 0; i < lines.size(); ++i)
    for (size_t j = std::max(i + 1, boundaryLines); j < lines.size(); ++j) {
      Line &p = lines[i], &q = lines[j];
      const auto& points = snapped.points();
      for (int id : {q.a, q.b}) splitIfOn(p, id, points[id], points, tolerance);
      for (int id : {p.a, p.b}) splitIfOn(q, id, points[id], points, tolerance);
      const Vec2 pa = points[p.a], pb = points[p.b], qa = points[q.a], qb = points[q.b];
      const Vec2 r = pb - pa, s = qb - qa;
      const double denominator = r.x * s.y - r.y * s.x;
      if (std::abs(denominator) <= 1e-300) continue;
      const Vec2 w = qa - pa;
      const double t = (w.x * s.y - w.y * s.x) / denominator, u = (w.x * r.y - w.y * r.x) / denominator;
      const double lp = glm::length(r), lq = glm::length(s);
      if (t * lp <= tolerance || (1 - t) * lp <= tolerance || u * lq <= tolerance || (1 - u) * lq <= tolerance)
        continue;  // no crossing, or one near an endpoint (handled above)
      const Vec2 x = pa + t * r;
      const int id = snapped.insert(x);
      splitIfOn(p, id, snapped.points()[id], snapped.points(), tolerance);
      splitIfOn(q, id, snapped.points()[id], snapped.points(), tolerance);
    }

  // Each line becomes its chain of pieces between consecutive points.
  auto chain = [](Line& line) {
    std::sort(line.splits.begin(), line.splits.end());
    std::vector<int> ids = {line.a};
    for (const auto& [t, id] : line.splits)
      if (id != ids.back()) ids.push_back(id);
    if (line.b != ids.back()) ids.push_back(line.b);
    return ids;
  };
  std::map<std::pair<int, int>, size_t> segmentAt;  // (low, high) point ids -> graph segment
  for (size_t i = 0; i < boundaryLines; ++i) {
    const std::vector<int> ids = chain(lines[i]);
    for (size_t k = 0; k + 1 < ids.size(); ++k) {
      result.graph.boundary.push_back(ids[k]);
      segmentAt[std::minmax(ids[k], ids[k + 1])] = SIZE_MAX;  // boundary: not a segment
    }
  }
  for (size_t i = boundaryLines; i < lines.size(); ++i) {
    const std::vector<int> ids = chain(lines[i]);
    for (size_t k = 0; k + 1 < ids.size(); ++k) {
      const auto key = std::minmax(ids[k], ids[k + 1]);
      auto [it, added] = segmentAt.emplace(key, result.graph.segments.size());
      if (added) {
        result.graph.segments.push_back({ids[k], ids[k + 1]});
        result.order.push_back(lines[i].order);
      } else if (it->second != SIZE_MAX && int(lines[i].order) < int(result.order[it->second])) {
        result.order[it->second] = lines[i].order;
      }
    }
  }
  result.graph.points = snapped.points();
  return result;
}

}  // namespace radview
