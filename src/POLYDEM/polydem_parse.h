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

// utils::numeric as LAMMPS 29 Sep 2021 has it, on every LAMMPS version: a
// word of the characters 0-9 + - . e E reads as atof (strtod) does, the
// range included (1e400 is inf, 1e-320 a subnormal: the callers test and
// name them); any other word is LAMMPS's error. Later LAMMPS stops on the
// range itself, with its own text ("out of range"), before a command can
// say which of its values is wrong.
inline double numeric(const char *file, int line, const char *word, LAMMPS_NS::LAMMPS *lmp)
{
  if (word && *word) {
    bool plain = true;
    for (const char *c = word; *c && plain; c++)
      plain = (*c >= '0' && *c <= '9') || *c == '+' || *c == '-' || *c == '.' || *c == 'e' ||
          *c == 'E';
    if (plain) return std::strtod(word, nullptr);
  }
  return LAMMPS_NS::utils::numeric(file, line, word ? word : "", false, lmp);
}

// a keyword of two words: true for `first`, false for `second`, else an
// error "cmd: kw expects first or second, got 'word'"
inline bool choice(const char *file, int line, LAMMPS_NS::LAMMPS *lmp, const std::string &cmd,
                   const char *kw, const char *word, const char *first, const char *second)
{
  const std::string w = word ? word : "";
  if (w != first && w != second)
    lmp->error->all(file, line, "{}: {} expects {} or {}, got '{}'", cmd, kw, first, second, w);
  return w == first;
}

// a finite number written in full; cmd names the command in the message
inline double number(const char *file, int line, const char *word, LAMMPS_NS::LAMMPS *lmp,
                     const std::string &cmd)
{
  const double v = numeric(file, line, word, lmp);
  char *end = nullptr;
  const double w = std::strtod(word, &end);    // (an underflow to a subnormal is a number)
  if (end == word || *end != '\0' || !std::isfinite(w) || w != v)
    lmp->error->all(file, line, "{}: '{}' is not a finite number", cmd, word);
  return v;
}

}    // namespace polydem_parse

#endif
