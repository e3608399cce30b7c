#include "corridor.h"

#include <algorithm>

namespace spira::geodesic {

Corridor::Corridor(const GeodesicMesh& mesh)
    : mesh_(&mesh), faceStamp_(mesh.mesh().faceCount(), 0), vertexStamp_(mesh.mesh().vertexCount(), 0)
{
}

void Corridor::reset()
{
  ++stamp_;
  if (stamp_ == 0) {  // wrapped around: clear for real once every 4 billion uses
    std::fill(faceStamp_.begin(), faceStamp_.end(), 0);
    std::fill(vertexStamp_.begin(), vertexStamp_.end(), 0);
    stamp_ = 1;
  }
  faces_.clear();
  vertices_.clear();
  whole_ = false;
}

void Corridor::addFace(int f)
{
  if (faceStamp_[size_t(f)] == stamp_) return;
  faceStamp_[size_t(f)] = stamp_;
  faces_.push_back(f);
  for (int v : mesh_->mesh().faces[size_t(f)])
    if (vertexStamp_[size_t(v)] != stamp_) {
      vertexStamp_[size_t(v)] = stamp_;
      vertices_.push_back(v);
    }
}

void Corridor::build(const std::vector<int>& seed, int rings)
{
  reset();
  for (int f : seed) addFace(f);
  size_t frontier = 0;  // faces_[frontier..] were added by the last ring
  for (int r = 0; r < rings; ++r) {
    const size_t end = faces_.size();
    for (size_t i = frontier; i < end; ++i)
      for (int k = 0; k < 3; ++k) {
        const int g = mesh_->faceAcross(3 * faces_[i] + k);
        if (g >= 0) addFace(g);
      }
    frontier = end;
  }
  closeFans();
}

int Corridor::fanStarts(int v) const
{
  int starts = 0;
  for (const int* c = mesh_->cornersBegin(v); c != mesh_->cornersEnd(v); ++c) {
    const int f = *c / 3, k = *c % 3;
    if (!containsFace(f)) continue;
    const int across = mesh_->faceAcross(3 * f + (k + 2) % 3);  // over the edge that ends at v
    if (across < 0 || !containsFace(across)) ++starts;
  }
  return starts;
}

void Corridor::closeFans()
{
  constexpr int kMaxPasses = 16;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    std::vector<int> pinched;
    for (int v : vertices_)
      if (fanStarts(v) > 1) pinched.push_back(v);
    if (pinched.empty()) return;
    addStars(pinched);
  }
}

void Corridor::buildWholeMesh()
{
  reset();
  for (size_t f = 0; f < mesh_->mesh().faceCount(); ++f) addFace(int(f));
  whole_ = true;
}

void Corridor::addStars(const std::vector<int>& vertices)
{
  for (int v : vertices)
    for (const int* c = mesh_->cornersBegin(v); c != mesh_->cornersEnd(v); ++c) addFace(*c / 3);
}

bool Corridor::isCut(int v) const
{
  if (whole_) return false;
  for (const int* c = mesh_->cornersBegin(v); c != mesh_->cornersEnd(v); ++c)
    if (!containsFace(*c / 3)) return true;
  return false;
}

}  // namespace spira::geodesic
