/*
 * fmi_glue.h - what the FMI 2.0 and 3.0 adapters (fmi2_cs.c, fmi3_cs.c)
 * share over the unit of csrc/fmu/rr_fmu.h: the log categories, messages
 * as a logger takes them, the type of a variable, and FMU states as bytes.
 */
#ifndef RR_FMI_GLUE_H
#define RR_FMI_GLUE_H

#include <stddef.h>
#include "fmu/rr_fmu.h"

/* the log categories of modelDescription.xml, in this order */
enum { RR_FMI_LOG_EVENTS = 0, RR_FMI_LOG_WARNING, RR_FMI_LOG_ERROR, RR_FMI_NLOG };
extern const char *const rr_fmi_log_names[RR_FMI_NLOG];

/* rr_fmi_log_category - the index of a category's name, or -1. */
int rr_fmi_log_category(const char *name);

/* rr_fmi_text - "function: message" into buf[len], each '%' doubled if
 * `escape` (an FMI 2 logger takes the message as a printf format). */
void rr_fmi_text(char *buf, size_t len, const char *function, const char *message, int escape);

/* rr_fmi_var_type - the type (enum rr_fmu_type) of variable vr, or -1 if none has it. */
int rr_fmi_var_type(const rr_fmu *m, unsigned vr);

/* rr_fmi_not_of_type - the message that vr is unknown or not a `type`
 * variable (type: the caller's name of its type) into m's message; RR_ERR_PARAM. */
int rr_fmi_not_of_type(rr_fmu *m, unsigned vr, const char *type);

/* The bytes of a saved state: a header (a mark, the FMU's token, the size
 * of the state) and the state.  rr_fmi_state_bytes: their number.
 * rr_fmi_state_write: into bytes[size]; rr_fmi_state_read: from
 * bytes[size] into *s.  0, or RR_ERR_PARAM with m's message (size wrong,
 * not a state of this FMU). */
size_t rr_fmi_state_bytes(void);
int rr_fmi_state_write(rr_fmu *m, const rr_fmu_state *s, unsigned char *bytes, size_t size);
int rr_fmi_state_read(rr_fmu *m, const unsigned char *bytes, size_t size, rr_fmu_state *s);

/* The unit's allocation (the contact table): calloc and free. */
void *rr_fmi_alloc(void *ctx, size_t bytes);
void rr_fmi_free(void *ctx, void *p);

#endif
