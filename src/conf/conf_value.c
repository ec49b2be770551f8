/* Numbers, integers, ranges and choices of configuration values, for every file kind alike. */
#include "conf/conf_value.h"
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One number at p, which starts it; *end after it. */
static int parse_one(const char *p, double *out, const char **end, const char **why)
{
    char *stop;
    /* strtod also reads hexadecimal floats (0x1p-1) and words (inf, nan): the first are refused
     * here, the others fail the finiteness test */
    const char *digits = p + (*p == '-' || *p == '+');
    if (digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X'))
        return -1;
    errno = 0;
    *out = strtod(p, &stop);
    if (stop == p)
        return -1;
    /* beyond a double's range either way: an overflow, or a denormal that has lost its digits */
    if (errno == ERANGE) {
        *why = "too large or too small for a double";
        return -1;
    }
    if (!isfinite(*out)) {
        *why = "not a finite number";
        return -1;
    }
    *end = stop;
    return 0;
}

int conf_parse_numbers(const char *text, double *out, int count, const char **why)
{
    const char *p = text;
    for (int i = 0; i < count; i++) {
        while (isspace((unsigned char)*p))
            p++;
        if (*p == '\0')
            return -1;
        const char *end;
        if (parse_one(p, &out[i], &end, why) != 0)
            return -1;
        /* "1,2" must not read as 1 followed by garbage that happens to parse later */
        if (*end != '\0' && !isspace((unsigned char)*end))
            return -1;
        p = end;
    }
    while (isspace((unsigned char)*p))
        p++;
    return *p == '\0' ? 0 : -1;
}

int conf_parse_integer(const char *text, long long *out)
{
    char *end;
    /* decimal digits, with a minus sign for a negative number: strtoll alone would also take a
     * plus sign, leading blanks and (base 0) a 0x prefix */
    if (!isdigit((unsigned char)text[text[0] == '-']))
        return -1;
    errno = 0;
    long long x = strtoll(text, &end, 10);
    if (end == text || errno == ERANGE)
        return -1;
    while (isspace((unsigned char)*end))
        end++;
    if (*end != '\0')
        return -1;
    *out = x;
    return 0;
}

int conf_in_range(double x, double lo, double hi, unsigned flags)
{
    if (flags & CONF_ABOVE_LO ? !(x > lo) : !(x >= lo))
        return 0;
    if (flags & CONF_BELOW_HI ? !(x < hi) : !(x <= hi))
        return 0;
    return 1;
}

void conf_describe_range(double lo, double hi, unsigned flags, char *buf, size_t len)
{
    int has_lo = isfinite(lo), has_hi = isfinite(hi);
    const char *gt = flags & CONF_ABOVE_LO ? ">" : ">=";
    const char *lt = flags & CONF_BELOW_HI ? "<" : "<=";
    if (has_lo && has_hi && !(flags & (CONF_ABOVE_LO | CONF_BELOW_HI)))
        snprintf(buf, len, " from %.15g to %.15g", lo, hi);
    else if (has_lo && has_hi)
        snprintf(buf, len, " %s %.15g and %s %.15g", gt, lo, lt, hi);
    else if (has_lo)
        snprintf(buf, len, " %s %.15g", gt, lo);
    else if (has_hi)
        snprintf(buf, len, " %s %.15g", lt, hi);
    else if (len > 0)
        buf[0] = '\0';
}

int conf_choice_find(const char *const *names, const char *text)
{
    for (int i = 0; names[i]; i++)
        if (strcmp(names[i], text) == 0)
            return i;
    return -1;
}

void conf_describe_choices(const char *const *names, char *buf, size_t len)
{
    size_t used = (size_t)snprintf(buf, len, "one of");
    for (int i = 0; names[i] && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, "%s %s", i ? "," : "", names[i]);
}

void conf_quote(const char *value, char *buf, size_t len)
{
    int n = (int)strlen(value);
    snprintf(buf, len, "\"%.*s%s\"", n > CONF_QUOTE_MAX ? CONF_QUOTE_MAX : n, value, n > CONF_QUOTE_MAX ? "..." : "");
}
