#pragma once
/// \file
/// The students the person logged in may read (their own cohorts' for an
/// instructor, all for an administrator), by name.

#include "db/Records.h"

#include <string>
#include <vector>

namespace colonosim::app {

[[nodiscard]] std::vector<std::string> readableTrainees(db::Records& records, const db::Actor& actor);

}  // namespace colonosim::app
