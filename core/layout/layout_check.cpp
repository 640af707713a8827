#include "layout/layout_check.h"

#include <algorithm>

#include "base/error.h"
#include "mesh/boundary_tangents.h"
#include "mesh/connectivity.h"

namespace tessera::layout {
namespace {

constexpr std::size_t kProblemsKept = 12;
constexpr std::int32_t kNoSide = -2;  // side_of() gives a patch id or -1 (the mesh boundary)

std::string vertex_list(const std::vector<Index>& vertices) {
  std::string text;
  for (std::size_t k = 0; k < vertices.size() && k < 8; ++k)
    text += (k ? ", " : "") + std::to_string(vertices[k]);
  return vertices.size() > 8 ? text + ", ..." : text;
}

class Checker {
 public:
  Checker(const Mesh& mesh, const Connectivity& c, const std::vector<std::int32_t>& patch)
      : mesh_(mesh), c_(c), patch_(patch) {}

  LayoutCheck run() {
    if (!check_cover()) return std::move(result_);
    reached_.assign(mesh_.face_count(), -1);
    leaving_patch_.assign(mesh_.vertex_count(), -1);
    leaving_.assign(mesh_.vertex_count(), kNoIndex);
    walked_.assign(c_.halfedge_count(), -1);
    counted_.assign(mesh_.vertex_count(), -1);
    find_nodes();
    std::vector<std::vector<Index>> faces(result_.patch_count);
    for (Index f = 0; f < mesh_.face_count(); ++f) faces[patch_[f]].push_back(f);
    result_.corners.resize(result_.patch_count);
    result_.neighbours.resize(result_.patch_count);
    for (std::int32_t p = 0; p < std::int32_t(result_.patch_count); ++p) check_patch(p, faces[p]);
    std::vector<std::int32_t>& faulty = result_.faulty_patches;
    std::sort(faulty.begin(), faulty.end());
    faulty.erase(std::unique(faulty.begin(), faulty.end()), faulty.end());
    return std::move(result_);
  }

 private:
  // A problem of patch p: p joins the faulty patches.
  void patch_problem(std::int32_t p, const std::string& text) {
    std::vector<std::int32_t>& faulty = result_.faulty_patches;
    if (faulty.empty() || faulty.back() != p) faulty.push_back(p);
    problem(text);
  }

  void problem(const std::string& text) {
    if (result_.problems.size() < kProblemsKept) result_.problems.push_back(text);
    ++result_.problem_count;
  }

  std::int32_t side_of(Index h) const {
    return c_.is_boundary_halfedge(h) ? -1 : patch_[c_.face[h]];
  }

  bool check_cover() {
    if (patch_.size() != mesh_.face_count()) {
      problem("there are " + std::to_string(patch_.size()) + " patch ids for " +
              std::to_string(mesh_.face_count()) + " faces");
      return false;
    }
    std::int32_t highest = -1;
    for (Index f = 0; f < patch_.size(); ++f) {
      if (patch_[f] < 0) {
        problem("face " + std::to_string(f) + " is in no patch");
        return false;
      }
      highest = std::max(highest, patch_[f]);
    }
    result_.patch_count = std::size_t(highest + 1);
    std::vector<bool> used(result_.patch_count, false);
    for (std::int32_t p : patch_) used[p] = true;
    for (std::size_t p = 0; p < used.size(); ++p)
      if (!used[p]) problem("patch id " + std::to_string(p) + " has no face");
    return true;
  }

  // Per vertex: whether the sides around it differ (two patches, or a patch and the mesh
  // boundary). Only those can be nodes or touch a patch twice; the others need no walk around.
  std::vector<bool> vertices_between_sides() const {
    std::vector<std::int32_t> first_side(mesh_.vertex_count(), kNoSide);
    std::vector<bool> between(mesh_.vertex_count(), false);
    for (Index h = 0; h < c_.halfedge_count(); ++h) {
      const Index v = c_.from_vertex(h);
      const std::int32_t side = side_of(h);
      if (first_side[v] == kNoSide) first_side[v] = side;
      if (first_side[v] != side) between[v] = true;
    }
    return between;
  }

  void find_nodes() {
    is_node_.assign(mesh_.vertex_count(), false);
    const std::vector<bool> between = vertices_between_sides();
    const std::vector<std::uint8_t> boundary_corner = boundary_tangents(mesh_, c_).corner;
    std::vector<Index> outgoing;
    std::vector<std::int32_t> run_sides;  // the side of each run of faces around v
    for (Index v = 0; v < mesh_.vertex_count(); ++v) {
      if (!between[v]) continue;
      outgoing_halfedges(c_, v, outgoing);
      const std::size_t n = outgoing.size();
      if (n == 0) continue;
      run_sides.clear();
      for (std::size_t k = 0; k < n; ++k) {
        const std::int32_t here = side_of(outgoing[k]);
        if (here != side_of(outgoing[(k + 1) % n])) run_sides.push_back(here);
      }
      const std::size_t runs = run_sides.size();
      std::sort(run_sides.begin(), run_sides.end());
      for (std::size_t k = 0; k + 1 < runs; ++k)
        if (run_sides[k] >= 0 && run_sides[k] == run_sides[k + 1] &&
            (k + 2 == runs || run_sides[k + 2] != run_sides[k]))
          patch_problem(run_sides[k], "patch " + std::to_string(run_sides[k]) +
                                          " touches itself at vertex " + std::to_string(v));
      bool node = runs >= 3;
      if (runs == 2 && c_.is_boundary_vertex(v)) node = boundary_corner[v] != 0;
      is_node_[v] = node;
      if (node) result_.nodes.push_back(v);
    }
  }

  // What one walk over the faces of a patch finds: its edge-connected pieces, its vertices and
  // edges (for the Euler characteristic), and the vertices its boundary halfedges leave.
  struct PatchWalk {
    std::size_t pieces = 0;
    long vertices = 0, edges = 0;
    std::vector<Index> starts;  // vertices with a boundary halfedge of p leaving them
  };

  // Depth-first over the faces of p from each face not reached yet; every halfedge of p counts
  // its vertex once and its edge once (a boundary edge on its p side), and a boundary halfedge is
  // kept as the one leaving its vertex (where p touches itself there, the last one in face order).
  PatchWalk walk_patch(const std::vector<Index>& faces, std::int32_t p) {
    PatchWalk walk;
    for (Index start : faces) {
      if (reached_[start] == p) continue;
      ++walk.pieces;
      stack_.assign(1, start);
      reached_[start] = p;
      while (!stack_.empty()) {
        const Index f = stack_.back();
        stack_.pop_back();
        for (Index h = mesh_.face_offsets[f]; h < mesh_.face_offsets[f + 1]; ++h) {
          const Index t = c_.twin[h];
          const Index v = c_.to_vertex[t];
          walk.vertices += counted_[v] != p;
          counted_[v] = p;
          const bool boundary = side_of(t) != p;
          walk.edges += boundary || h < t;
          if (boundary) {
            if (leaving_patch_[v] != p) {
              walk.starts.push_back(v);
              leaving_patch_[v] = p;
              leaving_[v] = h;
            } else {
              leaving_[v] = std::max(leaving_[v], h);  // halfedges are numbered in face order
            }
            continue;
          }
          const Index g = c_.face[t];
          if (reached_[g] == p) continue;
          reached_[g] = p;
          stack_.push_back(g);
        }
      }
    }
    return walk;
  }

  // The boundary loops of patch p, each as its halfedges in order (counterclockwise around p),
  // from the vertices walk_patch() found. Each loop starts at its least vertex.
  std::vector<std::vector<Index>> boundary_loops(std::vector<Index> starts, std::int32_t p) {
    std::sort(starts.begin(), starts.end());
    std::vector<std::vector<Index>> loops;
    for (Index vertex : starts) {
      if (walked_[leaving_[vertex]] == p) continue;
      loops.emplace_back();
      for (Index h = leaving_[vertex]; walked_[h] != p;) {
        walked_[h] = p;
        loops.back().push_back(h);
        const Index next = c_.to_vertex[h];
        if (leaving_patch_[next] != p) break;
        h = leaving_[next];
      }
    }
    return loops;
  }

  void check_patch(std::int32_t p, const std::vector<Index>& faces) {
    const std::string name = "patch " + std::to_string(p);
    PatchWalk walk = walk_patch(faces, p);
    const long chi = walk.vertices - walk.edges + long(faces.size());
    const std::vector<std::vector<Index>> loops = boundary_loops(std::move(walk.starts), p);
    if (walk.pieces != 1 || chi != 1 || loops.size() != 1) {
      patch_problem(p, name + " is not a disk (" + std::to_string(walk.pieces) +
                           " pieces, Euler characteristic " + std::to_string(chi) + ", " +
                           std::to_string(loops.size()) + " boundary loops)");
      return;
    }
    const std::vector<Index>& loop = loops.front();
    std::vector<std::size_t> at;  // positions of the corners in the loop
    for (std::size_t k = 0; k < loop.size(); ++k)
      if (is_node_[c_.from_vertex(loop[k])]) at.push_back(k);
    std::vector<Index>& corners = result_.corners[p];
    for (std::size_t k : at) corners.push_back(c_.from_vertex(loop[k]));
    if (corners.size() != 4) {
      patch_problem(p, name + " has " + std::to_string(corners.size()) + " corners (vertices " +
                           vertex_list(corners) + ")");
      return;
    }
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t begin = at[k], end = k + 1 < 4 ? at[k + 1] : at[0] + loop.size();
      const std::int32_t across = side_of(c_.twin[loop[begin]]);
      result_.neighbours[p].push_back(across);
      if (across < 0 || across < p) continue;
      LayoutArc arc{{}, p, across};
      for (std::size_t i = begin; i <= end; ++i)
        arc.vertices.push_back(c_.from_vertex(loop[i % loop.size()]));
      result_.arcs.push_back(std::move(arc));
    }
  }

  const Mesh& mesh_;
  const Connectivity& c_;
  const std::vector<std::int32_t>& patch_;
  std::vector<bool> is_node_;
  // Scratch of the per-patch walks, marked with the patch id so that no patch clears them.
  std::vector<std::int32_t> reached_;        // per face (walk_patch())
  std::vector<Index> stack_;                 // faces to visit (walk_patch())
  std::vector<std::int32_t> leaving_patch_;  // per vertex: p if leaving_ holds p's halfedge
  std::vector<Index> leaving_;               // per vertex (walk_patch(), boundary_loops())
  std::vector<std::int32_t> walked_;         // per halfedge (boundary_loops())
  std::vector<std::int32_t> counted_;        // per vertex (walk_patch())
  LayoutCheck result_;
};

}  // namespace

LayoutCheck check_layout(const Mesh& mesh, const Connectivity& connectivity,
                         const std::vector<std::int32_t>& patch) {
  return Checker(mesh, connectivity, patch).run();
}

LayoutCheck check_layout(const Mesh& mesh, const std::vector<std::int32_t>& patch) {
  Connectivity connectivity;
  try {
    connectivity = build_connectivity(mesh);
  } catch (const Error& e) {
    LayoutCheck result;
    result.problems.push_back(std::string("the refined mesh is not a manifold: ") + e.what());
    result.problem_count = 1;
    return result;
  }
  return check_layout(mesh, connectivity, patch);
}

}  // namespace tessera::layout
