#include "spira/ui/views/interaction_style.h"

#include <vtkObjectFactory.h>

namespace spira::ui {

vtkStandardNewMacro(QuietTrackballStyle);

}  // namespace spira::ui
