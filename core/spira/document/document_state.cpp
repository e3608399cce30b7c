#include "spira/document/document_state.h"

namespace spira {

bool DocumentState::sameInputs(const DocumentState& o) const
{
  return sameValue(part, o.part) && sameValue(substrate, o.substrate) && sameValue(cell, o.cell) &&
         sameValue(settings, o.settings) && sameValue(scan, o.scan);
}

}  // namespace spira
