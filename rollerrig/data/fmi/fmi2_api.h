/*
 * fmi2_api.h - the FMI 2.0 co-simulation interface as this FMU implements
 * it: the platform types ("default"), the status and callback types, and
 * the common and co-simulation functions, declared for the FMU's side.
 *
 * Written for rollerrig from the FMI 2.0 standard (Modelica Association,
 * https://fmi-standard.org; its headers are under the 2-clause BSD
 * licence): the names, the order of the enumerations and the functions'
 * arguments are the standard's, so that any FMI 2.0 importer can call
 * this FMU.  Compiled with FMI2_FUNCTION_PREFIX defined (a source-code FMU
 * linked statically), every function's name gets that prefix, as the
 * standard prescribes.
 */
#ifndef RR_FMI2_API_H
#define RR_FMI2_API_H

#include <stddef.h>

/* exported from the shared library (the rest of the library is hidden) */
#if defined _WIN32 || defined __CYGWIN__
#define RR_FMI2_EXPORT __declspec(dllexport)
#elif defined __GNUC__
#define RR_FMI2_EXPORT __attribute__((visibility("default")))
#else
#define RR_FMI2_EXPORT
#endif

#ifdef FMI2_FUNCTION_PREFIX
#define RR_FMI2_JOIN_(a, b) a##b
#define RR_FMI2_JOIN(a, b) RR_FMI2_JOIN_(a, b)
#define RR_FMI2_NAME(name) RR_FMI2_JOIN(FMI2_FUNCTION_PREFIX, name)
#define fmi2GetTypesPlatform RR_FMI2_NAME(fmi2GetTypesPlatform)
#define fmi2GetVersion RR_FMI2_NAME(fmi2GetVersion)
#define fmi2SetDebugLogging RR_FMI2_NAME(fmi2SetDebugLogging)
#define fmi2Instantiate RR_FMI2_NAME(fmi2Instantiate)
#define fmi2FreeInstance RR_FMI2_NAME(fmi2FreeInstance)
#define fmi2SetupExperiment RR_FMI2_NAME(fmi2SetupExperiment)
#define fmi2EnterInitializationMode RR_FMI2_NAME(fmi2EnterInitializationMode)
#define fmi2ExitInitializationMode RR_FMI2_NAME(fmi2ExitInitializationMode)
#define fmi2Terminate RR_FMI2_NAME(fmi2Terminate)
#define fmi2Reset RR_FMI2_NAME(fmi2Reset)
#define fmi2GetReal RR_FMI2_NAME(fmi2GetReal)
#define fmi2GetInteger RR_FMI2_NAME(fmi2GetInteger)
#define fmi2GetBoolean RR_FMI2_NAME(fmi2GetBoolean)
#define fmi2GetString RR_FMI2_NAME(fmi2GetString)
#define fmi2SetReal RR_FMI2_NAME(fmi2SetReal)
#define fmi2SetInteger RR_FMI2_NAME(fmi2SetInteger)
#define fmi2SetBoolean RR_FMI2_NAME(fmi2SetBoolean)
#define fmi2SetString RR_FMI2_NAME(fmi2SetString)
#define fmi2GetFMUstate RR_FMI2_NAME(fmi2GetFMUstate)
#define fmi2SetFMUstate RR_FMI2_NAME(fmi2SetFMUstate)
#define fmi2FreeFMUstate RR_FMI2_NAME(fmi2FreeFMUstate)
#define fmi2SerializedFMUstateSize RR_FMI2_NAME(fmi2SerializedFMUstateSize)
#define fmi2SerializeFMUstate RR_FMI2_NAME(fmi2SerializeFMUstate)
#define fmi2DeSerializeFMUstate RR_FMI2_NAME(fmi2DeSerializeFMUstate)
#define fmi2GetDirectionalDerivative RR_FMI2_NAME(fmi2GetDirectionalDerivative)
#define fmi2SetRealInputDerivatives RR_FMI2_NAME(fmi2SetRealInputDerivatives)
#define fmi2GetRealOutputDerivatives RR_FMI2_NAME(fmi2GetRealOutputDerivatives)
#define fmi2DoStep RR_FMI2_NAME(fmi2DoStep)
#define fmi2CancelStep RR_FMI2_NAME(fmi2CancelStep)
#define fmi2GetStatus RR_FMI2_NAME(fmi2GetStatus)
#define fmi2GetRealStatus RR_FMI2_NAME(fmi2GetRealStatus)
#define fmi2GetIntegerStatus RR_FMI2_NAME(fmi2GetIntegerStatus)
#define fmi2GetBooleanStatus RR_FMI2_NAME(fmi2GetBooleanStatus)
#define fmi2GetStringStatus RR_FMI2_NAME(fmi2GetStringStatus)
#endif

/* the "default" platform types */
typedef void *fmi2Component;
typedef void *fmi2ComponentEnvironment;
typedef void *fmi2FMUstate;
typedef unsigned int fmi2ValueReference;
typedef double fmi2Real;
typedef int fmi2Integer;
typedef int fmi2Boolean;
typedef char fmi2Char;
typedef const fmi2Char *fmi2String;
typedef char fmi2Byte;

#define fmi2True 1
#define fmi2False 0

typedef enum { fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal, fmi2Pending } fmi2Status;
typedef enum { fmi2ModelExchange, fmi2CoSimulation } fmi2Type;
typedef enum {
    fmi2DoStepStatus, fmi2PendingStatus, fmi2LastSuccessfulTime, fmi2Terminated
} fmi2StatusKind;

/* the importer's callbacks; the logger's message is a printf format */
typedef void (*fmi2CallbackLogger)(fmi2ComponentEnvironment environment, fmi2String instanceName,
                                   fmi2Status status, fmi2String category, fmi2String message,
                                   ...);
typedef void *(*fmi2CallbackAllocateMemory)(size_t nobj, size_t size);
typedef void (*fmi2CallbackFreeMemory)(void *obj);
typedef void (*fmi2StepFinished)(fmi2ComponentEnvironment environment, fmi2Status status);

typedef struct {
    fmi2CallbackLogger logger;
    fmi2CallbackAllocateMemory allocateMemory;
    fmi2CallbackFreeMemory freeMemory;
    fmi2StepFinished stepFinished;
    fmi2ComponentEnvironment componentEnvironment;
} fmi2CallbackFunctions;

/* common functions */
RR_FMI2_EXPORT const char *fmi2GetTypesPlatform(void);
RR_FMI2_EXPORT const char *fmi2GetVersion(void);
RR_FMI2_EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn,
                                              size_t nCategories, const fmi2String categories[]);
RR_FMI2_EXPORT fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType,
                                             fmi2String fmuGUID, fmi2String fmuResourceLocation,
                                             const fmi2CallbackFunctions *functions,
                                             fmi2Boolean visible, fmi2Boolean loggingOn);
RR_FMI2_EXPORT void fmi2FreeInstance(fmi2Component c);
RR_FMI2_EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                                              fmi2Real tolerance, fmi2Real startTime,
                                              fmi2Boolean stopTimeDefined, fmi2Real stopTime);
RR_FMI2_EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c);
RR_FMI2_EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c);
RR_FMI2_EXPORT fmi2Status fmi2Terminate(fmi2Component c);
RR_FMI2_EXPORT fmi2Status fmi2Reset(fmi2Component c);
RR_FMI2_EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[],
                                      size_t nvr, fmi2Real value[]);
RR_FMI2_EXPORT fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[],
                                         size_t nvr, fmi2Integer value[]);
RR_FMI2_EXPORT fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                                         size_t nvr, fmi2Boolean value[]);
RR_FMI2_EXPORT fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[],
                                        size_t nvr, fmi2String value[]);
RR_FMI2_EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[],
                                      size_t nvr, const fmi2Real value[]);
RR_FMI2_EXPORT fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[],
                                         size_t nvr, const fmi2Integer value[]);
RR_FMI2_EXPORT fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                                         size_t nvr, const fmi2Boolean value[]);
RR_FMI2_EXPORT fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[],
                                        size_t nvr, const fmi2String value[]);
RR_FMI2_EXPORT fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate);
RR_FMI2_EXPORT fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate);
RR_FMI2_EXPORT fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate);
RR_FMI2_EXPORT fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate,
                                                     size_t *size);
RR_FMI2_EXPORT fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate,
                                                fmi2Byte serializedState[], size_t size);
RR_FMI2_EXPORT fmi2Status fmi2DeSerializeFMUstate(fmi2Component c,
                                                  const fmi2Byte serializedState[],
                                                  size_t size, fmi2FMUstate *FMUstate);
RR_FMI2_EXPORT fmi2Status fmi2GetDirectionalDerivative(
    fmi2Component c, const fmi2ValueReference vUnknown_ref[], size_t nUnknown,
    const fmi2ValueReference vKnown_ref[], size_t nKnown, const fmi2Real dvKnown[],
    fmi2Real dvUnknown[]);

/* co-simulation functions */
RR_FMI2_EXPORT fmi2Status fmi2SetRealInputDerivatives(fmi2Component c,
                                                      const fmi2ValueReference vr[], size_t nvr,
                                                      const fmi2Integer order[],
                                                      const fmi2Real value[]);
RR_FMI2_EXPORT fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c,
                                                       const fmi2ValueReference vr[], size_t nvr,
                                                       const fmi2Integer order[],
                                                       fmi2Real value[]);
RR_FMI2_EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                                     fmi2Real communicationStepSize,
                                     fmi2Boolean noSetFMUStatePriorToCurrentPoint);
RR_FMI2_EXPORT fmi2Status fmi2CancelStep(fmi2Component c);
RR_FMI2_EXPORT fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s,
                                        fmi2Status *value);
RR_FMI2_EXPORT fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s,
                                            fmi2Real *value);
RR_FMI2_EXPORT fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s,
                                               fmi2Integer *value);
RR_FMI2_EXPORT fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s,
                                               fmi2Boolean *value);
RR_FMI2_EXPORT fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s,
                                              fmi2String *value);

#endif
