/*
 * fmi3_cs.c - the rig's co-simulation unit (csrc/fmu/rr_fmu.h) behind the
 * FMI 3.0 co-simulation interface, without event mode: after
 * fmi3ExitInitializationMode the instance is in step mode.  Every function
 * maps its arguments onto the unit, turns the unit's status into an
 * fmi3Status (0 fmi3OK, > 0 fmi3Warning, < 0 fmi3Error) and passes its
 * message to logMessage, prefixed by the function's name.  The variables
 * are Float64, Int32, Boolean and Enumeration (fmi3GetInt64, fmi3SetInt64);
 * every other function of the standard is here and refuses with a message
 * (model exchange, scheduled execution, event mode, clocks, derivatives).
 */
#include <stdlib.h>
#include <string.h>
#include "util/rr_common.h"
#include "fmi3_api.h"
#include "fmu_build.h"
#include "fmi_glue.h"

typedef struct {
    rr_fmu m;
    fmi3LogMessageCallback log;
    fmi3InstanceEnvironment env;
    int logging_on;
    int category_on[RR_FMI_NLOG];
} fmi3_unit;

static const char *const type_names[] = {"Float64", "Int32", "Boolean", "Int64 (enumeration)"};

static void log_to(fmi3LogMessageCallback log, fmi3InstanceEnvironment env, fmi3Status status,
                   int category, const char *function, const char *message)
{
    char text[RR_FMU_MSG_LEN + 256];
    if (!log)
        return;
    rr_fmi_text(text, sizeof text, function, message, 0);
    log(env, status, rr_fmi_log_names[category], text);
}

static void log_msg(fmi3_unit *in, fmi3Status status, int category, const char *function,
                    const char *message)
{
    if (!in->category_on[category] || (category == RR_FMI_LOG_EVENTS && !in->logging_on))
        return;
    log_to(in->log, in->env, status, category, function, message);
}

static fmi3Status result(fmi3_unit *in, const char *function, int st)
{
    if (st == RR_OK)
        return fmi3OK;
    if (st > 0) {
        log_msg(in, fmi3Warning, RR_FMI_LOG_WARNING, function, rr_fmu_message(&in->m));
        return fmi3Warning;
    }
    log_msg(in, fmi3Error, RR_FMI_LOG_ERROR, function, rr_fmu_message(&in->m));
    return fmi3Error;
}

static fmi3Status refuse(fmi3_unit *in, const char *function, const char *message)
{
    if (in)
        log_msg(in, fmi3Error, RR_FMI_LOG_ERROR, function, message);
    return fmi3Error;
}

static const char no_support[] = "not supported: a co-simulation FMU without event mode, "
                                 "clocks or derivatives";

/* ------------------------------------------------------------------ instances */

const char *fmi3GetVersion(void)
{
    return "3.0";
}

fmi3Status fmi3SetDebugLogging(fmi3Instance instance_, fmi3Boolean loggingOn,
                               size_t nCategories, const fmi3String categories[])
{
    fmi3_unit *in = instance_;
    size_t i;
    if (!in)
        return fmi3Error;
    if (nCategories > 0 && !categories)
        return refuse(in, "fmi3SetDebugLogging", "categories is NULL");
    for (i = 0; i < nCategories; i++)
        if (rr_fmi_log_category(categories[i]) < 0) {
            char text[200];
            rr_fmi_text(text, sizeof text, "unknown log category (this FMU has logEvents, "
                        "logStatusWarning, logStatusError)", categories[i], 0);
            return refuse(in, "fmi3SetDebugLogging", text);
        }
    if (nCategories == 0)
        in->logging_on = loggingOn;
    for (i = 0; i < nCategories; i++)
        in->category_on[rr_fmi_log_category(categories[i])] = loggingOn;
    if (nCategories > 0 && loggingOn)
        in->logging_on = 1;
    return fmi3OK;
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName,
                                          fmi3String instantiationToken,
                                          fmi3String resourcePath, fmi3Boolean visible,
                                          fmi3Boolean loggingOn,
                                          fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage)
{
    (void)instanceName;
    (void)instantiationToken;
    (void)resourcePath;
    (void)visible;
    (void)loggingOn;
    log_to(logMessage, instanceEnvironment, fmi3Error, RR_FMI_LOG_ERROR,
           "fmi3InstantiateModelExchange", "this FMU is for co-simulation only");
    return NULL;
}

fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
    fmi3LockPreemptionCallback lockPreemption, fmi3UnlockPreemptionCallback unlockPreemption)
{
    (void)instanceName;
    (void)instantiationToken;
    (void)resourcePath;
    (void)visible;
    (void)loggingOn;
    (void)clockUpdate;
    (void)lockPreemption;
    (void)unlockPreemption;
    log_to(logMessage, instanceEnvironment, fmi3Error, RR_FMI_LOG_ERROR,
           "fmi3InstantiateScheduledExecution", "this FMU is for co-simulation only");
    return NULL;
}

fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3IntermediateUpdateCallback intermediateUpdate)
{
    rr_fmu_config start;
    fmi3_unit *in;
    int k;
    (void)instanceName;
    (void)resourcePath;
    (void)visible;
    (void)earlyReturnAllowed;
    (void)requiredIntermediateVariables;
    (void)intermediateUpdate;
    if (!instantiationToken || strcmp(instantiationToken, rr_fmu_token) != 0) {
        char text[256];
        rr_fmi_text(text, sizeof text, "the instantiationToken is not this FMU's: its "
                    "modelDescription.xml belongs to another build; got",
                    instantiationToken ? instantiationToken : "NULL", 0);
        log_to(logMessage, instanceEnvironment, fmi3Error, RR_FMI_LOG_ERROR,
               "fmi3InstantiateCoSimulation", text);
        return NULL;
    }
    if (eventModeUsed) {
        log_to(logMessage, instanceEnvironment, fmi3Error, RR_FMI_LOG_ERROR,
               "fmi3InstantiateCoSimulation", "this FMU has no event mode (hasEventMode is "
               "false): instantiate it with eventModeUsed false");
        return NULL;
    }
    if (nRequiredIntermediateVariables > 0) {
        log_to(logMessage, instanceEnvironment, fmi3Error, RR_FMI_LOG_ERROR,
               "fmi3InstantiateCoSimulation", "this FMU provides no intermediate update");
        return NULL;
    }
    if (rr_fmu_start_config(&start) != RR_OK) {
        log_to(logMessage, instanceEnvironment, fmi3Error, RR_FMI_LOG_ERROR,
               "fmi3InstantiateCoSimulation", "the FMU's start values are refused by the "
               "rig's declaration (a build of another rollerrig version?)");
        return NULL;
    }
    in = calloc(1, sizeof *in);
    if (!in) {
        log_to(logMessage, instanceEnvironment, fmi3Error, RR_FMI_LOG_ERROR,
               "fmi3InstantiateCoSimulation", "out of memory");
        return NULL;
    }
    in->log = logMessage;
    in->env = instanceEnvironment;
    in->logging_on = loggingOn;
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
    log_msg(in, fmi3OK, RR_FMI_LOG_EVENTS, "fmi3InstantiateCoSimulation", "instantiated");
    return in;
}

void fmi3FreeInstance(fmi3Instance instance_)
{
    fmi3_unit *in = instance_;
    if (!in)
        return;
    rr_fmu_release(&in->m);
    free(in);
}

/* ------------------------------------------------------------------ modes */

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance_, fmi3Boolean toleranceDefined,
                                       fmi3Float64 tolerance, fmi3Float64 startTime,
                                       fmi3Boolean stopTimeDefined, fmi3Float64 stopTime)
{
    fmi3_unit *in = instance_;
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    if (!in)
        return fmi3Error;
    return result(in, "fmi3EnterInitializationMode", rr_fmu_enter_init(&in->m, startTime));
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance_)
{
    fmi3_unit *in = instance_;
    fmi3Status st;
    if (!in)
        return fmi3Error;
    st = result(in, "fmi3ExitInitializationMode", rr_fmu_exit_init(&in->m));
    if (st == fmi3OK)
        log_msg(in, fmi3OK, RR_FMI_LOG_EVENTS, "fmi3ExitInitializationMode",
                "the rig is built (contact table, parameters, initial state): step mode");
    return st;
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance_)
{
    return refuse(instance_, "fmi3EnterEventMode", no_support);
}

fmi3Status fmi3Terminate(fmi3Instance instance_)
{
    fmi3_unit *in = instance_;
    if (!in)
        return fmi3Error;
    return result(in, "fmi3Terminate", rr_fmu_terminate(&in->m));
}

fmi3Status fmi3Reset(fmi3Instance instance_)
{
    fmi3_unit *in = instance_;
    if (!in)
        return fmi3Error;
    log_msg(in, fmi3OK, RR_FMI_LOG_EVENTS, "fmi3Reset", "back to the start values");
    return result(in, "fmi3Reset", rr_fmu_reset(&in->m));
}

/* ------------------------------------------------------------------ values */

/* the arrays present and one value per reference (every variable is a scalar) */
static int arrays_ok(fmi3_unit *in, const char *function, const void *vr, size_t nvr,
                     const void *values, size_t nValues)
{
    if (nvr > 0 && (!vr || !values)) {
        refuse(in, function, "valueReferences or values is NULL");
        return 0;
    }
    if (nValues != nvr) {
        refuse(in, function, "nValues must equal nValueReferences: every variable of this "
               "FMU is a scalar");
        return 0;
    }
    return 1;
}

#define GET_AS(Name, T, TYPE, CONVERT)                                                      \
    fmi3Status fmi3Get##Name(RR_FMI3_VRS, T values[], size_t nValues)                       \
    {                                                                                       \
        fmi3_unit *in = instance;                                                            \
        size_t i;                                                                           \
        double x;                                                                           \
        int st;                                                                             \
        if (!in)                                                                            \
            return fmi3Error;                                                               \
        if (!arrays_ok(in, "fmi3Get" #Name, valueReferences, nValueReferences, values,      \
                       nValues))                                                            \
            return fmi3Error;                                                               \
        for (i = 0; i < nValueReferences; i++) {                                            \
            if ((st = rr_fmu_get(&in->m, TYPE, valueReferences[i], &x)) < 0)                \
                return result(in, "fmi3Get" #Name, st);                                     \
            values[i] = CONVERT;                                                            \
        }                                                                                   \
        return fmi3OK;                                                                      \
    }

#define SET_AS(Name, T, TYPE, CONVERT)                                                      \
    fmi3Status fmi3Set##Name(RR_FMI3_VRS, const T values[], size_t nValues)                 \
    {                                                                                       \
        fmi3_unit *in = instance;                                                            \
        size_t i;                                                                           \
        int st;                                                                             \
        if (!in)                                                                            \
            return fmi3Error;                                                               \
        if (!arrays_ok(in, "fmi3Set" #Name, valueReferences, nValueReferences, values,      \
                       nValues))                                                            \
            return fmi3Error;                                                               \
        for (i = 0; i < nValueReferences; i++)                                              \
            if ((st = rr_fmu_set(&in->m, TYPE, valueReferences[i], CONVERT)) < 0)           \
                return result(in, "fmi3Set" #Name, st);                                     \
        return fmi3OK;                                                                      \
    }

GET_AS(Float64, fmi3Float64, RR_FMU_REAL, x)
SET_AS(Float64, fmi3Float64, RR_FMU_REAL, values[i])
GET_AS(Int32, fmi3Int32, RR_FMU_INTEGER, (fmi3Int32)x)
SET_AS(Int32, fmi3Int32, RR_FMU_INTEGER, (double)values[i])
GET_AS(Int64, fmi3Int64, RR_FMU_ENUMERATION, (fmi3Int64)x)
SET_AS(Int64, fmi3Int64, RR_FMU_ENUMERATION, (double)values[i])
GET_AS(Boolean, fmi3Boolean, RR_FMU_BOOLEAN, x != 0.0)
SET_AS(Boolean, fmi3Boolean, RR_FMU_BOOLEAN, values[i] ? 1.0 : 0.0)

/* the types this FMU has no variables of: a reference is unknown or of another type */
#define NONE_OF(Name, T)                                                                    \
    fmi3Status fmi3Get##Name(RR_FMI3_VRS, T values[], size_t nValues)                       \
    {                                                                                       \
        fmi3_unit *in = instance;                                                            \
        if (!in)                                                                            \
            return fmi3Error;                                                               \
        if (!arrays_ok(in, "fmi3Get" #Name, valueReferences, nValueReferences, values,      \
                       nValues))                                                            \
            return fmi3Error;                                                               \
        if (nValueReferences == 0)                                                          \
            return fmi3OK;                                                                  \
        return result(in, "fmi3Get" #Name,                                                  \
                      rr_fmi_not_of_type(&in->m, valueReferences[0], #Name));               \
    }                                                                                       \
    fmi3Status fmi3Set##Name(RR_FMI3_VRS, const T values[], size_t nValues)                 \
    {                                                                                       \
        fmi3_unit *in = instance;                                                            \
        if (!in)                                                                            \
            return fmi3Error;                                                               \
        if (!arrays_ok(in, "fmi3Set" #Name, valueReferences, nValueReferences, values,      \
                       nValues))                                                            \
            return fmi3Error;                                                               \
        if (nValueReferences == 0)                                                          \
            return fmi3OK;                                                                  \
        return result(in, "fmi3Set" #Name,                                                  \
                      rr_fmi_not_of_type(&in->m, valueReferences[0], #Name));               \
    }

NONE_OF(Float32, fmi3Float32)
NONE_OF(Int8, fmi3Int8)
NONE_OF(UInt8, fmi3UInt8)
NONE_OF(Int16, fmi3Int16)
NONE_OF(UInt16, fmi3UInt16)
NONE_OF(UInt32, fmi3UInt32)
NONE_OF(UInt64, fmi3UInt64)
NONE_OF(String, fmi3String)

fmi3Status fmi3GetBinary(RR_FMI3_VRS, size_t valueSizes[], fmi3Binary values[], size_t nValues)
{
    fmi3_unit *in = instance;
    (void)valueSizes;
    if (!in)
        return fmi3Error;
    if (!arrays_ok(in, "fmi3GetBinary", valueReferences, nValueReferences, values, nValues))
        return fmi3Error;
    if (nValueReferences == 0)
        return fmi3OK;
    return result(in, "fmi3GetBinary", rr_fmi_not_of_type(&in->m, valueReferences[0], "Binary"));
}

fmi3Status fmi3SetBinary(RR_FMI3_VRS, const size_t valueSizes[], const fmi3Binary values[],
                         size_t nValues)
{
    fmi3_unit *in = instance;
    (void)valueSizes;
    if (!in)
        return fmi3Error;
    if (!arrays_ok(in, "fmi3SetBinary", valueReferences, nValueReferences, values, nValues))
        return fmi3Error;
    if (nValueReferences == 0)
        return fmi3OK;
    return result(in, "fmi3SetBinary", rr_fmi_not_of_type(&in->m, valueReferences[0], "Binary"));
}

fmi3Status fmi3GetClock(RR_FMI3_VRS, fmi3Clock values[])
{
    (void)valueReferences;
    (void)values;
    return nValueReferences == 0 && instance ? fmi3OK
                                             : refuse(instance, "fmi3GetClock", no_support);
}

fmi3Status fmi3SetClock(RR_FMI3_VRS, const fmi3Clock values[])
{
    (void)valueReferences;
    (void)values;
    return nValueReferences == 0 && instance ? fmi3OK
                                             : refuse(instance, "fmi3SetClock", no_support);
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance,
                                               fmi3ValueReference valueReference,
                                               size_t *nDependencies)
{
    (void)valueReference;
    (void)nDependencies;
    return refuse(instance, "fmi3GetNumberOfVariableDependencies", "not provided: the "
                  "outputs depend on every input and parameter (modelDescription.xml lists "
                  "no dependencies)");
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference dependent,
                                       size_t elementIndicesOfDependent[],
                                       fmi3ValueReference independents[],
                                       size_t elementIndicesOfIndependents[],
                                       fmi3DependencyKind dependencyKinds[],
                                       size_t nDependencies)
{
    (void)dependent;
    (void)elementIndicesOfDependent;
    (void)independents;
    (void)elementIndicesOfIndependents;
    (void)dependencyKinds;
    (void)nDependencies;
    return refuse(instance, "fmi3GetVariableDependencies", "not provided: the outputs "
                  "depend on every input and parameter");
}

/* ------------------------------------------------------------------ FMU states */

fmi3Status fmi3GetFMUState(fmi3Instance instance_, fmi3FMUState *FMUState)
{
    fmi3_unit *in = instance_;
    rr_fmu_state *s;
    if (!in)
        return fmi3Error;
    if (!FMUState)
        return refuse(in, "fmi3GetFMUState", "FMUState is NULL");
    s = *FMUState ? *FMUState : malloc(sizeof *s);
    if (!s)
        return refuse(in, "fmi3GetFMUState", "out of memory");
    rr_fmu_save(&in->m, s);
    *FMUState = s;
    return fmi3OK;
}

fmi3Status fmi3SetFMUState(fmi3Instance instance_, fmi3FMUState FMUState)
{
    fmi3_unit *in = instance_;
    if (!in)
        return fmi3Error;
    if (!FMUState)
        return refuse(in, "fmi3SetFMUState", "FMUState is NULL");
    return result(in, "fmi3SetFMUState", rr_fmu_restore(&in->m, FMUState));
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance_, fmi3FMUState *FMUState)
{
    if (!instance_)
        return fmi3Error;
    if (FMUState) {
        free(*FMUState);
        *FMUState = NULL;
    }
    return fmi3OK;
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance_, fmi3FMUState FMUState,
                                      size_t *size)
{
    fmi3_unit *in = instance_;
    if (!in)
        return fmi3Error;
    if (!FMUState || !size)
        return refuse(in, "fmi3SerializedFMUStateSize", "FMUState or size is NULL");
    *size = rr_fmi_state_bytes();
    return fmi3OK;
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance_, fmi3FMUState FMUState,
                                 fmi3Byte serializedState[], size_t size)
{
    fmi3_unit *in = instance_;
    if (!in)
        return fmi3Error;
    if (!FMUState)
        return refuse(in, "fmi3SerializeFMUState", "FMUState is NULL");
    return result(in, "fmi3SerializeFMUState",
                  rr_fmi_state_write(&in->m, FMUState, serializedState, size));
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance_, const fmi3Byte serializedState[],
                                   size_t size, fmi3FMUState *FMUState)
{
    fmi3_unit *in = instance_;
    rr_fmu_state *s;
    int st;
    if (!in)
        return fmi3Error;
    if (!FMUState)
        return refuse(in, "fmi3DeserializeFMUState", "FMUState is NULL");
    s = *FMUState ? *FMUState : malloc(sizeof *s);
    if (!s)
        return refuse(in, "fmi3DeserializeFMUState", "out of memory");
    if ((st = rr_fmi_state_read(&in->m, serializedState, size, s)) < 0) {
        if (!*FMUState)
            free(s);
        return result(in, "fmi3DeserializeFMUState", st);
    }
    *FMUState = s;
    return fmi3OK;
}

/* ------------------------------------------------------------------ not supported */

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance,
                                        const fmi3ValueReference unknowns[], size_t nUnknowns,
                                        const fmi3ValueReference knowns[], size_t nKnowns,
                                        const fmi3Float64 seed[], size_t nSeed,
                                        fmi3Float64 sensitivity[], size_t nSensitivity)
{
    (void)unknowns;
    (void)nUnknowns;
    (void)knowns;
    (void)nKnowns;
    (void)seed;
    (void)nSeed;
    (void)sensitivity;
    (void)nSensitivity;
    return refuse(instance, "fmi3GetDirectionalDerivative", no_support);
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[],
                                    size_t nUnknowns, const fmi3ValueReference knowns[],
                                    size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                    fmi3Float64 sensitivity[], size_t nSensitivity)
{
    (void)unknowns;
    (void)nUnknowns;
    (void)knowns;
    (void)nKnowns;
    (void)seed;
    (void)nSeed;
    (void)sensitivity;
    (void)nSensitivity;
    return refuse(instance, "fmi3GetAdjointDerivative", no_support);
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance)
{
    return refuse(instance, "fmi3EnterConfigurationMode", "no structural parameters");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance)
{
    return refuse(instance, "fmi3ExitConfigurationMode", "no structural parameters");
}

fmi3Status fmi3GetIntervalDecimal(RR_FMI3_VRS, fmi3Float64 intervals[],
                                  fmi3IntervalQualifier qualifiers[])
{
    (void)valueReferences;
    (void)nValueReferences;
    (void)intervals;
    (void)qualifiers;
    return refuse(instance, "fmi3GetIntervalDecimal", no_support);
}

fmi3Status fmi3GetIntervalFraction(RR_FMI3_VRS, fmi3UInt64 counters[], fmi3UInt64 resolutions[],
                                   fmi3IntervalQualifier qualifiers[])
{
    (void)valueReferences;
    (void)nValueReferences;
    (void)counters;
    (void)resolutions;
    (void)qualifiers;
    return refuse(instance, "fmi3GetIntervalFraction", no_support);
}

fmi3Status fmi3GetShiftDecimal(RR_FMI3_VRS, fmi3Float64 shifts[])
{
    (void)valueReferences;
    (void)nValueReferences;
    (void)shifts;
    return refuse(instance, "fmi3GetShiftDecimal", no_support);
}

fmi3Status fmi3GetShiftFraction(RR_FMI3_VRS, fmi3UInt64 counters[], fmi3UInt64 resolutions[])
{
    (void)valueReferences;
    (void)nValueReferences;
    (void)counters;
    (void)resolutions;
    return refuse(instance, "fmi3GetShiftFraction", no_support);
}

fmi3Status fmi3SetIntervalDecimal(RR_FMI3_VRS, const fmi3Float64 intervals[])
{
    (void)valueReferences;
    (void)nValueReferences;
    (void)intervals;
    return refuse(instance, "fmi3SetIntervalDecimal", no_support);
}

fmi3Status fmi3SetIntervalFraction(RR_FMI3_VRS, const fmi3UInt64 counters[],
                                   const fmi3UInt64 resolutions[])
{
    (void)valueReferences;
    (void)nValueReferences;
    (void)counters;
    (void)resolutions;
    return refuse(instance, "fmi3SetIntervalFraction", no_support);
}

fmi3Status fmi3SetShiftDecimal(RR_FMI3_VRS, const fmi3Float64 shifts[])
{
    (void)valueReferences;
    (void)nValueReferences;
    (void)shifts;
    return refuse(instance, "fmi3SetShiftDecimal", no_support);
}

fmi3Status fmi3SetShiftFraction(RR_FMI3_VRS, const fmi3UInt64 counters[],
                                const fmi3UInt64 resolutions[])
{
    (void)valueReferences;
    (void)nValueReferences;
    (void)counters;
    (void)resolutions;
    return refuse(instance, "fmi3SetShiftFraction", no_support);
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance)
{
    return refuse(instance, "fmi3EvaluateDiscreteStates", no_support);
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean *discreteStatesNeedUpdate,
                                    fmi3Boolean *terminateSimulation,
                                    fmi3Boolean *nominalsOfContinuousStatesChanged,
                                    fmi3Boolean *valuesOfContinuousStatesChanged,
                                    fmi3Boolean *nextEventTimeDefined,
                                    fmi3Float64 *nextEventTime)
{
    (void)discreteStatesNeedUpdate;
    (void)terminateSimulation;
    (void)nominalsOfContinuousStatesChanged;
    (void)valuesOfContinuousStatesChanged;
    (void)nextEventTimeDefined;
    (void)nextEventTime;
    return refuse(instance, "fmi3UpdateDiscreteStates", no_support);
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance)
{
    return refuse(instance, "fmi3EnterContinuousTimeMode", "a co-simulation FMU");
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance,
                                       fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi3Boolean *enterEventMode,
                                       fmi3Boolean *terminateSimulation)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    (void)enterEventMode;
    (void)terminateSimulation;
    return refuse(instance, "fmi3CompletedIntegratorStep", "a co-simulation FMU");
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time)
{
    (void)time;
    return refuse(instance, "fmi3SetTime", "a co-simulation FMU");
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64 continuousStates[],
                                   size_t nContinuousStates)
{
    (void)continuousStates;
    (void)nContinuousStates;
    return refuse(instance, "fmi3SetContinuousStates", "a co-simulation FMU");
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64 derivatives[],
                                             size_t nContinuousStates)
{
    (void)derivatives;
    (void)nContinuousStates;
    return refuse(instance, "fmi3GetContinuousStateDerivatives", "a co-simulation FMU");
}

fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64 eventIndicators[],
                                  size_t nEventIndicators)
{
    (void)eventIndicators;
    (void)nEventIndicators;
    return refuse(instance, "fmi3GetEventIndicators", "a co-simulation FMU");
}

fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64 continuousStates[],
                                   size_t nContinuousStates)
{
    (void)continuousStates;
    (void)nContinuousStates;
    return refuse(instance, "fmi3GetContinuousStates", "a co-simulation FMU");
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64 nominals[],
                                             size_t nContinuousStates)
{
    (void)nominals;
    (void)nContinuousStates;
    return refuse(instance, "fmi3GetNominalsOfContinuousStates", "a co-simulation FMU");
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t *nEventIndicators)
{
    (void)nEventIndicators;
    return refuse(instance, "fmi3GetNumberOfEventIndicators", "a co-simulation FMU");
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t *nContinuousStates)
{
    (void)nContinuousStates;
    return refuse(instance, "fmi3GetNumberOfContinuousStates", "a co-simulation FMU");
}

/* ------------------------------------------------------------------ co-simulation */

fmi3Status fmi3EnterStepMode(fmi3Instance instance)
{
    return refuse(instance, "fmi3EnterStepMode", "there is no event mode to leave: the "
                  "FMU is in step mode after fmi3ExitInitializationMode");
}

fmi3Status fmi3GetOutputDerivatives(RR_FMI3_VRS, const fmi3Int32 orders[], fmi3Float64 values[],
                                    size_t nValues)
{
    (void)valueReferences;
    (void)nValueReferences;
    (void)orders;
    (void)values;
    (void)nValues;
    return refuse(instance, "fmi3GetOutputDerivatives", "not provided "
                  "(maxOutputDerivativeOrder is 0)");
}

fmi3Status fmi3DoStep(fmi3Instance instance_, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation,
                      fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime)
{
    fmi3_unit *in = instance_;
    fmi3Status st;
    (void)noSetFMUStatePriorToCurrentPoint;
    if (!in)
        return fmi3Error;
    st = result(in, "fmi3DoStep",
                rr_fmu_do_step(&in->m, currentCommunicationPoint, communicationStepSize));
    if (eventHandlingNeeded)
        *eventHandlingNeeded = fmi3False;
    if (terminateSimulation)
        *terminateSimulation = fmi3False;
    if (earlyReturn)
        *earlyReturn = fmi3False;
    if (lastSuccessfulTime)
        *lastSuccessfulTime = rr_fmu_time(&in->m);
    return st;
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference clockReference,
                                      fmi3Float64 activationTime)
{
    (void)clockReference;
    (void)activationTime;
    return refuse(instance, "fmi3ActivateModelPartition", "a co-simulation FMU");
}
