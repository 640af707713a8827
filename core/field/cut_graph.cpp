#include "field/cut_graph.h"

#include <array>
#include <deque>
#include <numbers>

namespace tessera {

DualTree dual_spanning_tree(const Connectivity& c, const CrossField& field) {
  const std::size_t faces = field.angle.size();
  DualTree tree;
  tree.parent_halfedge.assign(faces, kNoIndex);
  tree.order.reserve(faces);
  std::vector<std::uint8_t> reached(faces, 0);
  // Two first-in-first-out queues, the zero-jump edges' served first: breadth-first within the
  // zero-jump regions (short tree paths, so the cut graph prunes well), then across jumps.
  std::array<std::deque<std::pair<Index, Index>>, 2> queues;  // (face, halfedge reaching it)
  for (Index root = 0; root < faces; ++root) {
    if (reached[root]) continue;
    queues[0].emplace_back(root, kNoIndex);
    while (!queues[0].empty() || !queues[1].empty()) {
      auto& queue = queues[0].empty() ? queues[1] : queues[0];
      const auto [f, via] = queue.front();
      queue.pop_front();
      if (reached[f]) continue;
      reached[f] = 1;
      tree.parent_halfedge[f] = via;
      tree.order.push_back(f);
      for (Index h = 3 * f; h < 3 * f + 3; ++h) {  // a triangle's corners are 3f, 3f+1, 3f+2
        const Index t = c.twin[h];
        if (c.is_boundary_halfedge(t) || reached[c.face[t]]) continue;
        queues[field.period_jump[h] == 0 ? 0 : 1].emplace_back(c.face[t], h);
      }
    }
  }
  return tree;
}

CrossField comb(const Connectivity& c, const FaceFrames& frames, const CrossField& field,
                const DualTree& tree) {
  std::vector<int> turns(field.angle.size(), 0);
  for (Index f : tree.order) {
    const Index h = tree.parent_halfedge[f];
    if (h != kNoIndex) turns[f] = (turns[c.face[h]] + field.period_jump[h]) % 4;
  }
  CrossField combed = field;
  for (Index f = 0; f < turns.size(); ++f) {
    combed.angle[f] = wrap_angle(field.angle[f] + turns[f] * std::numbers::pi / 2);
    combed.direction[f] = frames.direction(f, combed.angle[f]);
  }
  // theta'_f = theta_f + k_f pi/2 changes p_fg = round((theta_f + kappa - theta_g) / (pi/2)) by
  // k_f - k_g (cross_field.h).
  for (Index h = 0; h < c.corner_count; ++h) {
    const Index t = c.twin[h];
    if (c.is_boundary_halfedge(t)) continue;
    combed.period_jump[h] = static_cast<std::uint8_t>(
        (field.period_jump[h] + turns[c.face[h]] - turns[c.face[t]] + 8) % 4);
  }
  return combed;
}

std::vector<std::uint8_t> cut_graph(const Connectivity& c, const CrossField& field,
                                    const DualTree& tree) {
  std::vector<std::uint8_t> cut(c.edge_count(), 1);
  for (Index e = 0; e < c.edge_count(); ++e)
    if (c.is_boundary_edge(e)) cut[e] = 0;
  for (Index h : tree.parent_halfedge)
    if (h != kNoIndex) cut[c.edge[h]] = 0;

  std::vector<Index> degree(c.vertex_count(), 0);
  for (Index e = 0; e < c.edge_count(); ++e) {
    if (!cut[e]) continue;
    const Index h = c.edge_halfedge[e];
    ++degree[c.from_vertex(h)];
    ++degree[c.to_vertex[h]];
  }
  auto dangling = [&](Index v) {
    return degree[v] == 1 && field.vertex_index[v] == 0 && !c.is_boundary_vertex(v);
  };
  std::vector<Index> stack;
  for (Index v = 0; v < c.vertex_count(); ++v)
    if (dangling(v)) stack.push_back(v);
  while (!stack.empty()) {
    const Index v = stack.back();
    stack.pop_back();
    if (!dangling(v)) continue;
    for (Index h : outgoing_halfedges(c, v)) {
      if (!cut[c.edge[h]]) continue;
      cut[c.edge[h]] = 0;
      --degree[v];
      const Index w = c.to_vertex[h];
      --degree[w];
      if (dangling(w)) stack.push_back(w);
      break;
    }
  }
  return cut;
}

}  // namespace tessera
