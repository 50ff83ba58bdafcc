/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - strict number parsing for the package's commands. LAMMPS's
   utils::numeric accepts any mix of digits, signs, '.', 'e' and parses a
   prefix ("1e" reads as 1, "1.2.3" as 1.2); these read the whole word or
   stop with an error naming the command and the word.
------------------------------------------------------------------------- */

#ifndef LMP_POLYDEM_PARSE_H
#define LMP_POLYDEM_PARSE_H

#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <cmath>
#include <cstdlib>
#include <string>

namespace polydem_parse {

// a finite number written in full; cmd names the command in the message
inline double number(const char *file, int line, const char *word, LAMMPS_NS::LAMMPS *lmp,
                     const std::string &cmd)
{
  const double v = LAMMPS_NS::utils::numeric(file, line, word, false, lmp);
  char *end = nullptr;
  const double w = std::strtod(word, &end);    // (an underflow to a subnormal is a number)
  if (end == word || *end != '\0' || !std::isfinite(w) || w != v)
    lmp->error->all(file, line, "{}: '{}' is not a finite number", cmd, word);
  return v;
}

}    // namespace polydem_parse

#endif
