/* The values of a configuration key, read the same way for every file kind (scenes and the kiosk
 * configuration): numbers, integers, ranges and choices, and the words of their messages. A schema
 * keeps only its tables and what its keys set; what "a number" or "from 0 to 1" means is here.
 *
 * Numbers are decimal (strtod's form without its hexadecimal floats: nobody means 0x1p-1 for a
 * field of view or a knob's range), finite, and within a double's normal range (a denormal such as
 * 1e-320 is refused, as an overflow is). Integers are decimal digits with an optional minus sign:
 * no plus sign, no leading blanks, no 0x. */
#ifndef BT_CONF_VALUE_H
#define BT_CONF_VALUE_H
#include <stddef.h>

/* Flags of a key's range and of the key itself; a schema may add its own above CONF_FLAGS_OWN. */
#define CONF_ABOVE_LO 1u        /* value > lo instead of >= lo */
#define CONF_BELOW_HI 2u        /* value < hi instead of <= hi */
#define CONF_REQUIRED 4u        /* the section is incomplete without it */
#define CONF_FLAGS_OWN 16u

/* Values are quoted back in messages shortened to this many bytes, with "..." after. */
#define CONF_QUOTE_MAX 80

/* COUNT numbers separated by blanks, the whole text used (blanks around them allowed). 0, or -1;
 * on -1 *why says what was wrong beyond the expected form (not finite, out of a double's range),
 * or stays as it was. */
int conf_parse_numbers(const char *text, double *out, int count, const char **why);
/* One decimal integer, blanks after it allowed. 0, or -1 (also beyond long long). */
int conf_parse_integer(const char *text, long long *out);
/* Whether x lies in the range [lo, hi] with the ends that flags open. NaN is in no range. */
int conf_in_range(double x, double lo, double hi, unsigned flags);
/* " from 0 to 1", " > 0", " >= 1 and < 10", or "" for an unbounded range (infinite ends). */
void conf_describe_range(double lo, double hi, unsigned flags, char *buf, size_t len);
/* Index of TEXT in the NULL-terminated list NAMES, -1 if it is none of them. */
int conf_choice_find(const char *const *names, const char *text);
/* "one of a, b, c" */
void conf_describe_choices(const char *const *names, char *buf, size_t len);
/* The value as quoted in a message: "\"VALUE\"", cut at CONF_QUOTE_MAX bytes with "..." after. */
void conf_quote(const char *value, char *buf, size_t len);

#endif
