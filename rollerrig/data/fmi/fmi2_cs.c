/*
 * fmi2_cs.c - the rig's co-simulation unit (csrc/fmu/rr_fmu.h) behind the
 * FMI 2.0 co-simulation interface: every function maps its arguments onto
 * the unit, turns the unit's status into an fmi2Status (0 fmi2OK, > 0
 * fmi2Warning, < 0 fmi2Error) and passes its message to the logger,
 * prefixed by the function's name.  Warnings and errors are always logged
 * (unless a category is switched off by name with fmi2SetDebugLogging);
 * the unit's life (logEvents) when logging is on.  Integer functions
 * serve the Integer and the Enumeration variables.
 */
#include <stdlib.h>
#include <string.h>
#include "util/rr_common.h"
#include "fmi2_api.h"
#include "fmu_build.h"
#include "fmi_glue.h"

typedef struct {
    rr_fmu m;
    fmi2CallbackLogger logger;
    fmi2ComponentEnvironment env;
    char *name;
    int logging_on;
    int category_on[RR_FMI_NLOG];
    double start_time;
} fmi2_unit;

static const char *const type_names[] = {"Real", "Integer", "Boolean", "Integer (enumeration)"};

static void log_to(fmi2CallbackLogger logger, fmi2ComponentEnvironment env, const char *name,
                   fmi2Status status, int category, const char *function, const char *message)
{
    char text[RR_FMU_MSG_LEN + 256];
    if (!logger)
        return;
    rr_fmi_text(text, sizeof text, function, message, 1);
    logger(env, name, status, rr_fmi_log_names[category], text);
}

static void log_msg(fmi2_unit *in, fmi2Status status, int category, const char *function,
                    const char *message)
{
    if (!in->category_on[category] || (category == RR_FMI_LOG_EVENTS && !in->logging_on))
        return;
    log_to(in->logger, in->env, in->name, status, category, function, message);
}

/* the unit's status as an fmi2Status, its message logged */
static fmi2Status result(fmi2_unit *in, const char *function, int st)
{
    if (st == RR_OK)
        return fmi2OK;
    if (st > 0) {
        log_msg(in, fmi2Warning, RR_FMI_LOG_WARNING, function, rr_fmu_message(&in->m));
        return fmi2Warning;
    }
    log_msg(in, fmi2Error, RR_FMI_LOG_ERROR, function, rr_fmu_message(&in->m));
    return fmi2Error;
}

static fmi2Status refuse(fmi2_unit *in, const char *function, const char *message)
{
    log_msg(in, fmi2Error, RR_FMI_LOG_ERROR, function, message);
    return fmi2Error;
}

/* ------------------------------------------------------------------ common functions */

const char *fmi2GetTypesPlatform(void)
{
    return "default";
}

const char *fmi2GetVersion(void)
{
    return "2.0";
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[])
{
    fmi2_unit *in = c;
    size_t i;
    if (!in)
        return fmi2Error;
    if (nCategories > 0 && !categories)
        return refuse(in, "fmi2SetDebugLogging", "categories is NULL");
    for (i = 0; i < nCategories; i++)
        if (rr_fmi_log_category(categories[i]) < 0) {
            char text[200];
            rr_fmi_text(text, sizeof text, "unknown log category (this FMU has logEvents, "
                        "logStatusWarning, logStatusError)", categories[i], 0);
            return refuse(in, "fmi2SetDebugLogging", text);
        }
    if (nCategories == 0)
        in->logging_on = loggingOn != fmi2False;
    for (i = 0; i < nCategories; i++)
        in->category_on[rr_fmi_log_category(categories[i])] = loggingOn != fmi2False;
    if (nCategories > 0 && loggingOn)
        in->logging_on = 1;
    return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions *functions, fmi2Boolean visible,
                              fmi2Boolean loggingOn)
{
    const char *name = instanceName ? instanceName : "";
    fmi2CallbackLogger logger = functions ? functions->logger : NULL;
    fmi2ComponentEnvironment env = functions ? functions->componentEnvironment : NULL;
    rr_fmu_config start;
    fmi2_unit *in;
    int st, k;
    (void)fmuResourceLocation;
    (void)visible;
    if (!logger)
        return NULL;
    if (fmuType != fmi2CoSimulation) {
        log_to(logger, env, name, fmi2Error, RR_FMI_LOG_ERROR, "fmi2Instantiate",
               "this FMU is for co-simulation only (fmuType fmi2CoSimulation)");
        return NULL;
    }
    if (!fmuGUID || strcmp(fmuGUID, rr_fmu_token) != 0) {
        char text[256];
        rr_fmi_text(text, sizeof text, "the GUID is not this FMU's: its modelDescription.xml "
                    "belongs to another build; got", fmuGUID ? fmuGUID : "NULL", 0);
        log_to(logger, env, name, fmi2Error, RR_FMI_LOG_ERROR, "fmi2Instantiate", text);
        return NULL;
    }
    if ((st = rr_fmu_start_config(&start)) != RR_OK) {
        log_to(logger, env, name, fmi2Error, RR_FMI_LOG_ERROR, "fmi2Instantiate",
               "the FMU's start values are refused by the rig's declaration (a build of "
               "another rollerrig version?)");
        return NULL;
    }
    in = calloc(1, sizeof *in);
    if (in)
        in->name = malloc(strlen(name) + 1);
    if (!in || !in->name) {
        free(in);
        log_to(logger, env, name, fmi2Error, RR_FMI_LOG_ERROR, "fmi2Instantiate",
               "out of memory");
        return NULL;
    }
    strcpy(in->name, name);
    in->logger = logger;
    in->env = env;
    in->logging_on = loggingOn != fmi2False;
    for (k = 0; k < RR_FMI_NLOG; k++)
        in->category_on[k] = 1;
    rr_fmu_init(&in->m, &start, rr_fmi_alloc, rr_fmi_free, NULL, type_names);
    {   /* the real profiles' points the build generated (none for the cone) */
        rr_rig_profiles points;
        rr_nh_table nonhertz[2];
        rr_fmu_start_profiles(&points);
        rr_fmu_set_profiles(&in->m, &points);
        if (rr_fmu_start_nonhertz(nonhertz))
            rr_fmu_set_nonhertz(&in->m, &nonhertz[0], &nonhertz[1]);
    }
    log_msg(in, fmi2OK, RR_FMI_LOG_EVENTS, "fmi2Instantiate", "instantiated");
    return in;
}

void fmi2FreeInstance(fmi2Component c)
{
    fmi2_unit *in = c;
    if (!in)
        return;
    rr_fmu_release(&in->m);
    free(in->name);
    free(in);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                               fmi2Real tolerance, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    fmi2_unit *in = c;
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    if (!in)
        return fmi2Error;
    if (in->m.s.mode != RR_FMU_INSTANTIATED)
        return refuse(in, "fmi2SetupExperiment", "allowed only after fmi2Instantiate or "
                      "fmi2Reset");
    in->start_time = startTime;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    fmi2_unit *in = c;
    if (!in)
        return fmi2Error;
    return result(in, "fmi2EnterInitializationMode", rr_fmu_enter_init(&in->m, in->start_time));
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    fmi2_unit *in = c;
    fmi2Status st;
    if (!in)
        return fmi2Error;
    st = result(in, "fmi2ExitInitializationMode", rr_fmu_exit_init(&in->m));
    if (st == fmi2OK)
        log_msg(in, fmi2OK, RR_FMI_LOG_EVENTS, "fmi2ExitInitializationMode",
                "the rig is built (contact table, parameters, initial state): stepping");
    return st;
}

fmi2Status fmi2Terminate(fmi2Component c)
{
    fmi2_unit *in = c;
    if (!in)
        return fmi2Error;
    return result(in, "fmi2Terminate", rr_fmu_terminate(&in->m));
}

fmi2Status fmi2Reset(fmi2Component c)
{
    fmi2_unit *in = c;
    if (!in)
        return fmi2Error;
    in->start_time = 0.0;
    log_msg(in, fmi2OK, RR_FMI_LOG_EVENTS, "fmi2Reset", "back to the start values");
    return result(in, "fmi2Reset", rr_fmu_reset(&in->m));
}

/* ------------------------------------------------------------------ values */

static fmi2Status check_arrays(fmi2_unit *in, const char *function, size_t n, const void *vr,
                               const void *value)
{
    if (n > 0 && (!vr || !value))
        return refuse(in, function, "vr or value is NULL");
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[])
{
    fmi2_unit *in = c;
    size_t i;
    int st;
    if (!in)
        return fmi2Error;
    if (check_arrays(in, "fmi2GetReal", nvr, vr, value) != fmi2OK)
        return fmi2Error;
    for (i = 0; i < nvr; i++)
        if ((st = rr_fmu_get(&in->m, RR_FMU_REAL, vr[i], &value[i])) < 0)
            return result(in, "fmi2GetReal", st);
    return fmi2OK;
}

/* Integer functions: Integer and Enumeration variables */
static int integer_type(fmi2_unit *in, fmi2ValueReference vr)
{
    return rr_fmi_var_type(&in->m, vr) == RR_FMU_ENUMERATION ? RR_FMU_ENUMERATION
                                                             : RR_FMU_INTEGER;
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[])
{
    fmi2_unit *in = c;
    size_t i;
    double x;
    int st;
    if (!in)
        return fmi2Error;
    if (check_arrays(in, "fmi2GetInteger", nvr, vr, value) != fmi2OK)
        return fmi2Error;
    for (i = 0; i < nvr; i++) {
        if ((st = rr_fmu_get(&in->m, integer_type(in, vr[i]), vr[i], &x)) < 0)
            return result(in, "fmi2GetInteger", st);
        value[i] = (fmi2Integer)x;
    }
    return fmi2OK;
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[])
{
    fmi2_unit *in = c;
    size_t i;
    double x;
    int st;
    if (!in)
        return fmi2Error;
    if (check_arrays(in, "fmi2GetBoolean", nvr, vr, value) != fmi2OK)
        return fmi2Error;
    for (i = 0; i < nvr; i++) {
        if ((st = rr_fmu_get(&in->m, RR_FMU_BOOLEAN, vr[i], &x)) < 0)
            return result(in, "fmi2GetBoolean", st);
        value[i] = x != 0.0 ? fmi2True : fmi2False;
    }
    return fmi2OK;
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[])
{
    fmi2_unit *in = c;
    if (!in)
        return fmi2Error;
    if (check_arrays(in, "fmi2GetString", nvr, vr, value) != fmi2OK)
        return fmi2Error;
    if (nvr == 0)
        return fmi2OK;
    return result(in, "fmi2GetString", rr_fmi_not_of_type(&in->m, vr[0], "String"));
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[])
{
    fmi2_unit *in = c;
    size_t i;
    int st;
    if (!in)
        return fmi2Error;
    if (check_arrays(in, "fmi2SetReal", nvr, vr, value) != fmi2OK)
        return fmi2Error;
    for (i = 0; i < nvr; i++)
        if ((st = rr_fmu_set(&in->m, RR_FMU_REAL, vr[i], value[i])) < 0)
            return result(in, "fmi2SetReal", st);
    return fmi2OK;
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[])
{
    fmi2_unit *in = c;
    size_t i;
    int st;
    if (!in)
        return fmi2Error;
    if (check_arrays(in, "fmi2SetInteger", nvr, vr, value) != fmi2OK)
        return fmi2Error;
    for (i = 0; i < nvr; i++)
        if ((st = rr_fmu_set(&in->m, integer_type(in, vr[i]), vr[i], value[i])) < 0)
            return result(in, "fmi2SetInteger", st);
    return fmi2OK;
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[])
{
    fmi2_unit *in = c;
    size_t i;
    int st;
    if (!in)
        return fmi2Error;
    if (check_arrays(in, "fmi2SetBoolean", nvr, vr, value) != fmi2OK)
        return fmi2Error;
    for (i = 0; i < nvr; i++)
        if ((st = rr_fmu_set(&in->m, RR_FMU_BOOLEAN, vr[i], value[i] ? 1.0 : 0.0)) < 0)
            return result(in, "fmi2SetBoolean", st);
    return fmi2OK;
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[])
{
    fmi2_unit *in = c;
    if (!in)
        return fmi2Error;
    if (check_arrays(in, "fmi2SetString", nvr, vr, value) != fmi2OK)
        return fmi2Error;
    if (nvr == 0)
        return fmi2OK;
    return result(in, "fmi2SetString", rr_fmi_not_of_type(&in->m, vr[0], "String"));
}

/* ------------------------------------------------------------------ FMU states */

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    fmi2_unit *in = c;
    rr_fmu_state *s;
    if (!in)
        return fmi2Error;
    if (!FMUstate)
        return refuse(in, "fmi2GetFMUstate", "FMUstate is NULL");
    s = *FMUstate ? *FMUstate : malloc(sizeof *s);
    if (!s)
        return refuse(in, "fmi2GetFMUstate", "out of memory");
    rr_fmu_save(&in->m, s);
    *FMUstate = s;
    return fmi2OK;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate)
{
    fmi2_unit *in = c;
    if (!in)
        return fmi2Error;
    if (!FMUstate)
        return refuse(in, "fmi2SetFMUstate", "FMUstate is NULL");
    return result(in, "fmi2SetFMUstate", rr_fmu_restore(&in->m, FMUstate));
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    fmi2_unit *in = c;
    if (!in)
        return fmi2Error;
    if (FMUstate) {
        free(*FMUstate);
        *FMUstate = NULL;
    }
    return fmi2OK;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size)
{
    fmi2_unit *in = c;
    if (!in)
        return fmi2Error;
    if (!FMUstate || !size)
        return refuse(in, "fmi2SerializedFMUstateSize", "FMUstate or size is NULL");
    *size = rr_fmi_state_bytes();
    return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate,
                                 fmi2Byte serializedState[], size_t size)
{
    fmi2_unit *in = c;
    if (!in)
        return fmi2Error;
    if (!FMUstate)
        return refuse(in, "fmi2SerializeFMUstate", "FMUstate is NULL");
    return result(in, "fmi2SerializeFMUstate",
                  rr_fmi_state_write(&in->m, FMUstate, (unsigned char *)serializedState, size));
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[],
                                   size_t size, fmi2FMUstate *FMUstate)
{
    fmi2_unit *in = c;
    rr_fmu_state *s;
    int st;
    if (!in)
        return fmi2Error;
    if (!FMUstate)
        return refuse(in, "fmi2DeSerializeFMUstate", "FMUstate is NULL");
    s = *FMUstate ? *FMUstate : malloc(sizeof *s);
    if (!s)
        return refuse(in, "fmi2DeSerializeFMUstate", "out of memory");
    st = rr_fmi_state_read(&in->m, (const unsigned char *)serializedState, size, s);
    if (st < 0) {
        if (!*FMUstate)
            free(s);
        return result(in, "fmi2DeSerializeFMUstate", st);
    }
    *FMUstate = s;
    return fmi2OK;
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c,
                                        const fmi2ValueReference vUnknown_ref[],
                                        size_t nUnknown, const fmi2ValueReference vKnown_ref[],
                                        size_t nKnown, const fmi2Real dvKnown[],
                                        fmi2Real dvUnknown[])
{
    fmi2_unit *in = c;
    (void)vUnknown_ref;
    (void)nUnknown;
    (void)vKnown_ref;
    (void)nKnown;
    (void)dvKnown;
    (void)dvUnknown;
    if (!in)
        return fmi2Error;
    return refuse(in, "fmi2GetDirectionalDerivative", "not provided "
                  "(providesDirectionalDerivative is false)");
}

/* ------------------------------------------------------------------ co-simulation */

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[],
                                       size_t nvr, const fmi2Integer order[],
                                       const fmi2Real value[])
{
    fmi2_unit *in = c;
    (void)vr;
    (void)nvr;
    (void)order;
    (void)value;
    if (!in)
        return fmi2Error;
    return refuse(in, "fmi2SetRealInputDerivatives", "the inputs are held over a step "
                  "(canInterpolateInputs is false)");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[],
                                        size_t nvr, const fmi2Integer order[],
                                        fmi2Real value[])
{
    fmi2_unit *in = c;
    (void)vr;
    (void)nvr;
    (void)order;
    (void)value;
    if (!in)
        return fmi2Error;
    return refuse(in, "fmi2GetRealOutputDerivatives", "not provided "
                  "(maxOutputDerivativeOrder is 0)");
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint)
{
    fmi2_unit *in = c;
    (void)noSetFMUStatePriorToCurrentPoint;
    if (!in)
        return fmi2Error;
    return result(in, "fmi2DoStep",
                  rr_fmu_do_step(&in->m, currentCommunicationPoint, communicationStepSize));
}

fmi2Status fmi2CancelStep(fmi2Component c)
{
    fmi2_unit *in = c;
    if (!in)
        return fmi2Error;
    return refuse(in, "fmi2CancelStep", "fmi2DoStep is never pending "
                  "(canRunAsynchronuously is false)");
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value)
{
    fmi2_unit *in = c;
    (void)s;
    (void)value;
    if (!in)
        return fmi2Error;
    return fmi2Discard;             /* fmi2DoStep is never pending: no status to ask for */
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value)
{
    fmi2_unit *in = c;
    if (!in)
        return fmi2Error;
    if (s != fmi2LastSuccessfulTime || !value)
        return fmi2Discard;
    *value = rr_fmu_time(&in->m);
    return fmi2OK;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value)
{
    fmi2_unit *in = c;
    (void)s;
    (void)value;
    return in ? fmi2Discard : fmi2Error;
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value)
{
    fmi2_unit *in = c;
    if (!in)
        return fmi2Error;
    if (s != fmi2Terminated || !value)
        return fmi2Discard;
    *value = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value)
{
    fmi2_unit *in = c;
    (void)s;
    (void)value;
    return in ? fmi2Discard : fmi2Error;
}
