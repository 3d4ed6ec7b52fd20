/* fmi_glue.c - what the FMI adapters share (fmi_glue.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util/rr_common.h"
#include "fmu_build.h"
#include "fmi_glue.h"

const char *const rr_fmi_log_names[RR_FMI_NLOG] = {"logEvents", "logStatusWarning",
                                                   "logStatusError"};

int rr_fmi_log_category(const char *name)
{
    int i;
    for (i = 0; name && i < RR_FMI_NLOG; i++)
        if (strcmp(rr_fmi_log_names[i], name) == 0)
            return i;
    return -1;
}

void rr_fmi_text(char *buf, size_t len, const char *function, const char *message, int escape)
{
    size_t n = 0;
    const char *parts[3];
    int k;
    if (!buf || len == 0)
        return;
    parts[0] = function ? function : "";
    parts[1] = function ? ": " : "";
    parts[2] = message ? message : "";
    for (k = 0; k < 3; k++) {
        const char *s;
        for (s = parts[k]; *s && n + 2 < len; s++) {
            if (*s == '%' && escape)
                buf[n++] = '%';
            buf[n++] = *s;
        }
    }
    buf[n] = '\0';
}

int rr_fmi_var_type(const rr_fmu *m, unsigned vr)
{
    rr_fmu_var v;
    return m && rr_fmu_var_find(&m->start, vr, &v) == RR_OK ? v.type : -1;
}

int rr_fmi_not_of_type(rr_fmu *m, unsigned vr, const char *type)
{
    rr_fmu_var v;
    char name[RR_FMU_NAME_LEN];
    if (rr_fmu_var_find(&m->start, vr, &v) != RR_OK) {
        snprintf(m->msg, sizeof m->msg, "unknown value reference %u (no variable has it)", vr);
    } else {
        rr_fmu_var_name(&v, name, sizeof name);
        snprintf(m->msg, sizeof m->msg, "%s (value reference %u) is of type %s, not %s",
                 name, vr, m->type_names[v.type], type);
    }
    return RR_ERR_PARAM;
}

/* the header of a state's bytes */
typedef struct {
    char mark[32];
    char token[64];
    unsigned long long size;
} state_header;

static const char state_mark[] = "rollerrig FMU state, layout 1";

size_t rr_fmi_state_bytes(void)
{
    return sizeof(state_header) + sizeof(rr_fmu_state);
}

int rr_fmi_state_write(rr_fmu *m, const rr_fmu_state *s, unsigned char *bytes, size_t size)
{
    state_header h;
    if (!s || !bytes || size != rr_fmi_state_bytes()) {
        snprintf(m->msg, sizeof m->msg, "the state takes %lu bytes (fmi2SerializedFMUstateSize, "
                 "fmi3SerializedFMUStateSize), got a buffer of %lu",
                 (unsigned long)rr_fmi_state_bytes(), (unsigned long)size);
        return RR_ERR_PARAM;
    }
    memset(&h, 0, sizeof h);
    strncpy(h.mark, state_mark, sizeof h.mark - 1);
    strncpy(h.token, rr_fmu_token, sizeof h.token - 1);
    h.size = sizeof *s;
    memcpy(bytes, &h, sizeof h);
    memcpy(bytes + sizeof h, s, sizeof *s);
    return RR_OK;
}

int rr_fmi_state_read(rr_fmu *m, const unsigned char *bytes, size_t size, rr_fmu_state *s)
{
    state_header h;
    if (!bytes || size != rr_fmi_state_bytes()) {
        snprintf(m->msg, sizeof m->msg, "a state of this FMU is %lu bytes, got %lu",
                 (unsigned long)rr_fmi_state_bytes(), (unsigned long)size);
        return RR_ERR_PARAM;
    }
    memcpy(&h, bytes, sizeof h);
    h.mark[sizeof h.mark - 1] = h.token[sizeof h.token - 1] = '\0';
    if (strcmp(h.mark, state_mark) != 0 || strncmp(h.token, rr_fmu_token, sizeof h.token - 1) != 0
        || h.size != sizeof *s) {
        snprintf(m->msg, sizeof m->msg, "the bytes are not a state of this FMU (token %s): "
                 "states pass only between FMUs of one build", rr_fmu_token);
        return RR_ERR_PARAM;
    }
    memcpy(s, bytes + sizeof h, sizeof *s);
    return RR_OK;
}

void *rr_fmi_alloc(void *ctx, size_t bytes)
{
    (void)ctx;
    return calloc(1, bytes);
}

void rr_fmi_free(void *ctx, void *p)
{
    (void)ctx;
    free(p);
}
