#pragma once

#include "spira/path/trajectory.h"

namespace spira {

// A band of revolutions to lay with a thinner deposit: revolutions first..last of sub-path `path`
// (their indices in the trajectory), and the ratio of the new mean deposit to the planned one.
struct ThinningZone {
  int path = 0;
  int first = 0;  // the revolution the band rests on; it is kept as planned
  int last = 0;   // the revolution the band ends on; the thinned band ends exactly on it
  double ratio = 1.0;
};

struct ThinningResult {
  Trajectory trajectory;
  int revolutionsAdded = 0;
  double ratio = 1.0;       // the ratio laid: a whole number of revolutions fills the band
  int first = 0, last = 0;  // the band in the new trajectory's revolution numbers
};

// The source's remedy for a zone that overheats (000_dbb97c2716e10cc3.txt §5.6.4): the same band of
// the part laid with more, thinner revolutions. The band's n = last - first planned steps become
// n' = ceil(n / ratio) revolutions, and each generatrix (a point's place in its revolution) lays its
// band's deposit in n' equal layers: revolution j sits where that generatrix has climbed j / n' of it,
// between the planned revolutions. So the band ends on the planned revolution `last`, the rest of the
// path is unchanged, and ramps inside the band (those that level an upper edge) are spread over it.
// The bead's cross-section follows the new height as WFS / TS (the process model's own assumption,
// process_model.h): on a path fed at one wire speed (synergic) the travel speed rises, otherwise the
// wire feed drops. Frames and extra channels are interpolated between the planned revolutions.
// The band's revolutions must have the same number of points (a closed part's last revolution, its
// closure point alone, cannot be in it). Throws InputError when the band does not exist, is shorter
// than one revolution or mixes revolution lengths.
ThinningResult thinRevolutions(const Trajectory& planned, const ThinningZone& zone);

}  // namespace spira
