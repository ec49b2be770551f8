#include "render/path.h"
#include <stdio.h>
#include <string.h>

static void explain_formats(const struct gl_caps *c, int fp32, char *out, size_t n)
{
    size_t used = 0;
    out[0] = '\0';
    for (int i = 0; i < c->n_formats && used < n; i++)
        if (c->formats[i].is_fp32 == fp32)
            used += snprintf(out + used, n - used, "%s%s: %s", used ? "; " : "", c->formats[i].name,
                             c->formats[i].works ? "works" : c->formats[i].why);
    if (!used)
        snprintf(out, n, "no %s format is known for this API", fp32 ? "32-bit" : "16-bit");
}

int render_path_choose(const struct gl_caps *c, enum precision_choice precision, enum mrt_choice mrt,
                       struct render_path *p, char *err, size_t errlen)
{
    char why32[400], why16[400];
    memset(p, 0, sizeof *p);
    explain_formats(c, 1, why32, sizeof why32);
    explain_formats(c, 0, why16, sizeof why16);
    const struct float_format *f32 = caps_format(c, 1), *f16 = caps_format(c, 0);
    if (precision == PRECISION_FP32 && !f32) {
        snprintf(err, errlen, "--precision fp32: no 32-bit float render target works here (%s)", why32);
        return -1;
    }
    if (precision == PRECISION_FP16 && !f16) {
        snprintf(err, errlen, "--precision fp16: no 16-bit float render target works here (%s)", why16);
        return -1;
    }
    if (!f32 && !f16) {
        snprintf(err, errlen, "this GPU has no renderable float format for the ray state (%s; %s); "
                              "bentray needs RGBA32F or RGBA16F render targets",
                 why32, why16);
        return -1;
    }
    p->format = (precision == PRECISION_FP16 || !f32) ? f16 : f32;
    p->fp32 = p->format->is_fp32;
    if (mrt == MRT_ON && !c->mrt_works) {
        snprintf(err, errlen, "mrt=on: multiple render targets do not work here (%s)", c->mrt_why);
        return -1;
    }
    p->mrt = mrt != MRT_OFF && c->mrt_works;
    p->name = p->fp32 ? (p->mrt ? "fp32+mrt" : "fp32") : (p->mrt ? "fp16+mrt" : "fp16");
    snprintf(p->description, sizeof p->description, "%s: %s ray state, %s%s", p->name, p->format->name,
             p->mrt ? "x and v written by one pass (MRT)" : "x and v written in separate passes",
             p->fp32 ? "" : " (reduced accuracy: 16-bit floats)");
    return 0;
}
