#pragma once
// The untangle budget of dg-harmonic's last resort (docs/dg-harmonic.md):
// the repair that `dgwarp deform` (and the Python package) runs on its own
// when a dg-harmonic step inverts cells. It is an automatic step, so it must
// give up quickly where no local repair exists: SU2's bricks with the top face
// turned inside fixed walls, the case it is for, are repaired in 1-2 rounds;
// a pin of SU2's pin array moved while its nodes on the fixed walls tear those
// walls (cells no volume motion can unfold) ran all 12 rounds the default
// budget allowed and 43 s on 10,800 nodes before failing.
#include "dgwarp/repair/untangle.hpp"

namespace dgwarp {

/// Rounds of the last resort: three times what the bricks need.
constexpr int last_resort_max_rounds = 6;

/// The untangle options of the last resort (inverted cells only).
inline UntangleOptions last_resort_untangle_options() {
    UntangleOptions o;
    o.max_rounds = last_resort_max_rounds;
    return o;
}

}  // namespace dgwarp
