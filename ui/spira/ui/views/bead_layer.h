#pragma once

#include <array>
#include <vector>

#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkType.h>

#include "spira/base/transform.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace spira {
struct KinematicsResult;
}

namespace spira::ui {

// What the simulation draws over the part: the bead deposited so far (a tube along the path up to
// the current point), red markers where the torch or a robot link collides or the robot cannot
// reach (up to the current point), and a marker at the current point.
//
// The tube is made in chunks of kChunk points: complete chunks are tubed once and kept, so a
// frame of playback tubes only the chunk the torch is in (a whole-path tube per frame cost
// about 100 ms on 16,000 points in software OpenGL).
class BeadLayer {
 public:
  explicit BeadLayer(vtkRenderer* renderer);
  ~BeadLayer();

  // The solved motion (null clears), drawn where T_scene_part places the part; `beadRadius` mm.
  void setMotion(const KinematicsResult* motion, const Transform& T_scene_part, double beadRadius);
  // Shows the build up to point `index` included.
  void showUpTo(size_t index);
  void setVisible(bool on);
  // Flagged points (collision or unreachable) shown at the current index.
  long long shownFlagCount() const { return shownFlags_; }
  long long shownBeadPoints() const { return shownPoints_; }
  vtkActor* beadActor() const { return bead_; }          // the chunk being laid
  vtkActor* finishedActor() const { return finished_; }  // the complete chunks before it
  // Bounds of the whole bead shown (both actors); empty bounds (min > max) without a bead.
  std::array<double, 6> beadBounds() const;
  static constexpr size_t kChunk = 256;
  vtkActor* flagActor() const { return flags_; }

 private:
  vtkSmartPointer<vtkRenderer> renderer_;  // kept alive until the layer's actors are removed
  // The bead's polylines over points [first, last]: one per arc-on run of one sub-path.
  vtkSmartPointer<vtkPolyData> tubeOf(size_t first, size_t last) const;
  void showFinishedChunks(size_t count);

  vtkNew<vtkPolyData> path_;
  double radius_ = 1.0;
  std::vector<vtkSmartPointer<vtkPolyData>> chunkTubes_;  // made on first use
  size_t finishedChunks_ = 0;                             // shown in finished_
  vtkNew<vtkActor> bead_;
  vtkNew<vtkActor> finished_;
  std::vector<size_t> flagged_;  // indices of flagged points, ascending
  vtkNew<vtkPolyData> flagPoints_;
  vtkNew<vtkActor> flags_;
  vtkNew<vtkPolyData> current_;
  vtkNew<vtkActor> currentActor_;
  const KinematicsResult* motion_ = nullptr;
  bool visible_ = true;
  long long shownFlags_ = 0;
  long long shownPoints_ = 0;
  vtkIdType tipCells_ = 0;
};

}  // namespace spira::ui
