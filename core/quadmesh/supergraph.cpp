#include "quadmesh/supergraph.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "base/error.h"

namespace tessera::quadmesh {
namespace {

using layout::EdgeKind;
using layout::GraphEdge;
using layout::PortGraph;

// The halfedge from `from` to `to` of a connectivity, one with a face, or kNoIndex.
Index halfedge_between(const Connectivity& c, Index from, Index to) {
  for (Index h : outgoing_halfedges(c, from))
    if (c.to_vertex[h] == to && !c.is_boundary_halfedge(h)) return h;
  return kNoIndex;
}

// Where a line passes a regular vertex: the line (= its port), L there, and the halfedge it leaves
// along.
struct Visit {
  Index line = 0;
  Index length = 0;
  Index leaving = 0;
};

// A slope L_height / L_base as a fraction, compared exactly.
struct Slope {
  Index height = 1;
  Index base = 1;
  bool inclusive = true;  // the first window admits 45 degrees (case 3)
  bool admits(Index h, Index b) const {
    const std::uint64_t left = std::uint64_t(h) * base, right = std::uint64_t(height) * b;
    return inclusive ? left <= right : left < right;
  }
};

class Builder {
 public:
  Builder(const Mesh& quads, const Connectivity& c, const IntegerCharts& charts,
          const BaseComplex& base, const SupergraphOptions& options)
      : quads_(quads), c_(c), charts_(charts), base_(base), options_(options) {}

  Supergraph run() {
    result_.graph.ports = layout::find_ports(charts_.charts());
    map_ports();
    collect_visits();
    add_separatrix_edges();
    for (Index line = 0; line < line_count(); ++line) add_crossing_edges(line);
    return std::move(result_);
  }

 private:
  std::size_t line_count() const { return result_.graph.port_count(); }

  // Port p (layout/ports.h) leaves its vertex along the first edge of its triangle corner, an
  // edge of the quad mesh: its separatrix of B is the line starting with that quad halfedge.
  void map_ports() {
    const layout::Ports& ports = result_.graph.ports;
    port_of_halfedge_.assign(c_.halfedge_count(), kNoIndex);
    line_of_port_.resize(ports.ports.size());
    for (Index p = 0; p < ports.ports.size(); ++p) {
      const Index corner = ports.ports[p].corner;
      const Index from = charts_.triangles.face_vertices[corner];
      const Index to = charts_.connectivity.to_vertex[corner];
      const Index h = halfedge_between(c_, from, to);
      const Index line = h == kNoIndex ? kNoIndex : base_.line_of_halfedge[h];
      if (line == kNoIndex)
        throw Error("build_supergraph(): port " + std::to_string(p) + " at vertex " +
                    std::to_string(from) + " is no separatrix of B");
      port_of_halfedge_[h] = p;
      line_of_port_[p] = line;
    }
  }

  const BaseLine& line_of(Index port) const { return base_.lines[line_of_port_[port]]; }

  void collect_visits() {
    visit_offsets_.assign(quads_.vertex_count() + 1, 0);
    for (Index p = 0; p < line_count(); ++p) {
      const BaseLine& line = line_of(p);
      for (std::size_t k = 1; k < line.length(); ++k)
        ++visit_offsets_[c_.to_vertex[line.halfedges[k - 1]] + 1];
    }
    for (std::size_t v = 0; v < quads_.vertex_count(); ++v)
      visit_offsets_[v + 1] += visit_offsets_[v];
    visits_.resize(visit_offsets_.back());
    std::vector<Index> fill(visit_offsets_.begin(), visit_offsets_.end() - 1);
    for (Index p = 0; p < line_count(); ++p) {
      const BaseLine& line = line_of(p);
      for (std::size_t k = 1; k < line.length(); ++k)
        visits_[fill[c_.to_vertex[line.halfedges[k - 1]]]++] = {p, Index(k), line.halfedges[k]};
    }
  }

  // Sec. 4.4 and the separatrices of B themselves: height 0.
  void add_separatrix_edges() {
    PortGraph& graph = result_.graph;
    graph.separatrices.resize(line_count());
    for (Index p = 0; p < line_count(); ++p) {
      const BaseLine& line = line_of(p);
      layout::Separatrix& s = graph.separatrices[p];
      s.length = double(line.length());
      s.steps = line.length();
      const Index last = line.halfedges.back();
      s.end_vertex = c_.to_vertex[last];
      GraphEdge edge;
      edge.u = p;
      edge.base_line = p;
      edge.base = double(line.length());
      edge.side = -1;
      if (line.end == LineEnd::boundary) {
        s.end = layout::LineEnd::boundary;
        const Index t = halfedge_between(charts_.connectivity, c_.from_vertex(last), s.end_vertex);
        edge.kind = EdgeKind::boundary;
        edge.v = static_cast<Index>(graph.node_count());
        graph.virtual_ports.push_back({p, edge.base, charts_.connectivity.face[t],
                                       charts_.param.uv[charts_.connectivity.next[t]]});
      } else {
        s.end = layout::LineEnd::singularity;
        const Index hit = port_of_halfedge_[c_.twin[last]];
        // Both ends of a separatrix between two ports trace it: one edge.
        if (hit == kNoIndex || hit == p || hit < p) continue;
        edge.kind = EdgeKind::singularity;
        edge.v = hit;
      }
      graph.edges.push_back(edge);
      ++result_.separatrix_edges;
    }
  }

  // Condition C1 with the window reduction for the crossings at which `base` is the longer line,
  // in the order of its length there (Sec. 4.1, 4.2, 7.4).
  void add_crossing_edges(Index base) {
    const BaseLine& line = line_of(base);
    Slope window[2];  // per side: +1 (far singularity on the right), -1
    for (std::size_t k = 1; k < line.length(); ++k) {
      const Index m = c_.to_vertex[line.halfedges[k - 1]];
      const Index leaving = line.halfedges[k];
      for (Index i = visit_offsets_[m]; i < visit_offsets_[m + 1]; ++i) {
        const Visit& other = visits_[i];
        if (other.length > k) continue;
        // The height line turns counterclockwise from the base (side +1: it comes from the
        // right) or clockwise (-1); parallel lines do not cross.
        const int side = other.leaving == c_.next_outgoing(leaving)   ? 1
                         : leaving == c_.next_outgoing(other.leaving) ? -1
                                                                      : 0;
        if (side == 0) continue;
        const bool diagonal = other.length == k;
        // Each crossing once: from its longer line, or from one of two equal ones.
        if (!diagonal || other.line > base) ++result_.graph.crossing_count;
        if (diagonal && !options_.diagonals) continue;
        Slope& w = window[side > 0 ? 0 : 1];
        if (!w.admits(other.length, Index(k))) {
          ++result_.rejected_by_window;
          continue;
        }
        w = {other.length, Index(k), false};
        add_edge(base, Index(k), other.line, other.length, side, m);
      }
    }
  }

  void add_edge(Index base, Index base_length, Index height, Index height_length, int side,
                Index m) {
    PortGraph& graph = result_.graph;
    const Index far = graph.ports.neighbour(height, side);
    if (far == kNoIndex || far == base) return;
    const Index index = static_cast<Index>(graph.edges.size());
    graph.edges.push_back(
        layout::crossing_edge(base, far, height, base_length, height_length, side));
    ++result_.crossing_edges;
    if (base_length != height_length) return;
    // Case 3: the other line's edge at the same crossing makes the zero-area pair.
    const auto key = std::make_tuple(m, std::min(base, height), std::max(base, height));
    auto [it, added] = diagonal_at_.emplace(key, index);
    graph.edges[index].diagonal = true;
    ++result_.diagonal_edges;
    if (added) return;
    graph.zero_area.push_back({std::min(it->second, index), std::max(it->second, index)});
  }

  const Mesh& quads_;
  const Connectivity& c_;
  const IntegerCharts& charts_;
  const BaseComplex& base_;
  const SupergraphOptions& options_;
  Supergraph result_;
  std::vector<Index> port_of_halfedge_;  // quad halfedge -> port
  std::vector<Index> line_of_port_;
  std::vector<Index> visit_offsets_;  // per vertex, into visits_
  std::vector<Visit> visits_;
  std::map<std::tuple<Index, Index, Index>, Index> diagonal_at_;
};

}  // namespace

Supergraph build_supergraph(const Mesh& quads, const Connectivity& connectivity,
                            const IntegerCharts& charts, const BaseComplex& base,
                            const SupergraphOptions& options) {
  return Builder(quads, connectivity, charts, base, options).run();
}

}  // namespace tessera::quadmesh
