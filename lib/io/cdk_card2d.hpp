// CARD 2D, 2D1 and 2D2 of the .cdk deck (IHAZE 7 or ICLD 11): user-defined aerosol or
// cloud coefficients, read and written in LOWTRAN 7's columns (subroutine RDEXA of
// lowtran7.f; man cdk(5)). Internal to lib/io: cdk.cpp reads, cdk_write.cpp writes.
#pragma once

#include <functional>
#include <string>

#include "io/cdk.hpp"
#include "io/fortran_columns.hpp"

namespace sigchain::io {

// The next card of the deck, named for messages, with its field layout.
using CdkNextCard =
    std::function<fortran::Card(const std::string& name, const std::string& layout)>;

// Reads CARD 2D and, for each region with IREG 1, CARD 2D1 and the 16 lines of CARD
// 2D2; throws DataError naming the card, field and columns of the first problem.
CdkUserOptics read_cdk_card2d(const CdkNextCard& next);

}  // namespace sigchain::io
