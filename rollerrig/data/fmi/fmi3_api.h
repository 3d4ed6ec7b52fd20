/*
 * fmi3_api.h - the FMI 3.0 interface as this FMU implements it: the
 * platform types, the status, dependency and callback types, and every
 * function of the standard's fmi3Functions.h (an FMI 3.0 FMU exports them
 * all, those of the interfaces and capabilities it lacks too), declared
 * for the FMU's side.
 *
 * Written for rollerrig from the FMI 3.0 standard (Modelica Association,
 * https://fmi-standard.org; its headers are under the 2-clause BSD
 * licence): the names, the order of the enumerations and the functions'
 * arguments are the standard's, so that any FMI 3.0 importer can call
 * this FMU.  Compiled with FMI3_FUNCTION_PREFIX defined, every function's
 * name gets that prefix, as the standard prescribes.
 */
#ifndef RR_FMI3_API_H
#define RR_FMI3_API_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#if defined _WIN32 || defined __CYGWIN__
#define RR_FMI3_EXPORT __declspec(dllexport)
#elif defined __GNUC__
#define RR_FMI3_EXPORT __attribute__((visibility("default")))
#else
#define RR_FMI3_EXPORT
#endif

#ifdef FMI3_FUNCTION_PREFIX
#define RR_FMI3_JOIN_(a, b) a##b
#define RR_FMI3_JOIN(a, b) RR_FMI3_JOIN_(a, b)
#define RR_FMI3_NAME(name) RR_FMI3_JOIN(FMI3_FUNCTION_PREFIX, name)
#define fmi3GetVersion RR_FMI3_NAME(fmi3GetVersion)
#define fmi3SetDebugLogging RR_FMI3_NAME(fmi3SetDebugLogging)
#define fmi3InstantiateModelExchange RR_FMI3_NAME(fmi3InstantiateModelExchange)
#define fmi3InstantiateCoSimulation RR_FMI3_NAME(fmi3InstantiateCoSimulation)
#define fmi3InstantiateScheduledExecution RR_FMI3_NAME(fmi3InstantiateScheduledExecution)
#define fmi3FreeInstance RR_FMI3_NAME(fmi3FreeInstance)
#define fmi3EnterInitializationMode RR_FMI3_NAME(fmi3EnterInitializationMode)
#define fmi3ExitInitializationMode RR_FMI3_NAME(fmi3ExitInitializationMode)
#define fmi3EnterEventMode RR_FMI3_NAME(fmi3EnterEventMode)
#define fmi3Terminate RR_FMI3_NAME(fmi3Terminate)
#define fmi3Reset RR_FMI3_NAME(fmi3Reset)
#define fmi3GetFloat32 RR_FMI3_NAME(fmi3GetFloat32)
#define fmi3GetFloat64 RR_FMI3_NAME(fmi3GetFloat64)
#define fmi3GetInt8 RR_FMI3_NAME(fmi3GetInt8)
#define fmi3GetUInt8 RR_FMI3_NAME(fmi3GetUInt8)
#define fmi3GetInt16 RR_FMI3_NAME(fmi3GetInt16)
#define fmi3GetUInt16 RR_FMI3_NAME(fmi3GetUInt16)
#define fmi3GetInt32 RR_FMI3_NAME(fmi3GetInt32)
#define fmi3GetUInt32 RR_FMI3_NAME(fmi3GetUInt32)
#define fmi3GetInt64 RR_FMI3_NAME(fmi3GetInt64)
#define fmi3GetUInt64 RR_FMI3_NAME(fmi3GetUInt64)
#define fmi3GetBoolean RR_FMI3_NAME(fmi3GetBoolean)
#define fmi3GetString RR_FMI3_NAME(fmi3GetString)
#define fmi3GetBinary RR_FMI3_NAME(fmi3GetBinary)
#define fmi3GetClock RR_FMI3_NAME(fmi3GetClock)
#define fmi3SetFloat32 RR_FMI3_NAME(fmi3SetFloat32)
#define fmi3SetFloat64 RR_FMI3_NAME(fmi3SetFloat64)
#define fmi3SetInt8 RR_FMI3_NAME(fmi3SetInt8)
#define fmi3SetUInt8 RR_FMI3_NAME(fmi3SetUInt8)
#define fmi3SetInt16 RR_FMI3_NAME(fmi3SetInt16)
#define fmi3SetUInt16 RR_FMI3_NAME(fmi3SetUInt16)
#define fmi3SetInt32 RR_FMI3_NAME(fmi3SetInt32)
#define fmi3SetUInt32 RR_FMI3_NAME(fmi3SetUInt32)
#define fmi3SetInt64 RR_FMI3_NAME(fmi3SetInt64)
#define fmi3SetUInt64 RR_FMI3_NAME(fmi3SetUInt64)
#define fmi3SetBoolean RR_FMI3_NAME(fmi3SetBoolean)
#define fmi3SetString RR_FMI3_NAME(fmi3SetString)
#define fmi3SetBinary RR_FMI3_NAME(fmi3SetBinary)
#define fmi3SetClock RR_FMI3_NAME(fmi3SetClock)
#define fmi3GetNumberOfVariableDependencies RR_FMI3_NAME(fmi3GetNumberOfVariableDependencies)
#define fmi3GetVariableDependencies RR_FMI3_NAME(fmi3GetVariableDependencies)
#define fmi3GetFMUState RR_FMI3_NAME(fmi3GetFMUState)
#define fmi3SetFMUState RR_FMI3_NAME(fmi3SetFMUState)
#define fmi3FreeFMUState RR_FMI3_NAME(fmi3FreeFMUState)
#define fmi3SerializedFMUStateSize RR_FMI3_NAME(fmi3SerializedFMUStateSize)
#define fmi3SerializeFMUState RR_FMI3_NAME(fmi3SerializeFMUState)
#define fmi3DeserializeFMUState RR_FMI3_NAME(fmi3DeserializeFMUState)
#define fmi3GetDirectionalDerivative RR_FMI3_NAME(fmi3GetDirectionalDerivative)
#define fmi3GetAdjointDerivative RR_FMI3_NAME(fmi3GetAdjointDerivative)
#define fmi3EnterConfigurationMode RR_FMI3_NAME(fmi3EnterConfigurationMode)
#define fmi3ExitConfigurationMode RR_FMI3_NAME(fmi3ExitConfigurationMode)
#define fmi3GetIntervalDecimal RR_FMI3_NAME(fmi3GetIntervalDecimal)
#define fmi3GetIntervalFraction RR_FMI3_NAME(fmi3GetIntervalFraction)
#define fmi3GetShiftDecimal RR_FMI3_NAME(fmi3GetShiftDecimal)
#define fmi3GetShiftFraction RR_FMI3_NAME(fmi3GetShiftFraction)
#define fmi3SetIntervalDecimal RR_FMI3_NAME(fmi3SetIntervalDecimal)
#define fmi3SetIntervalFraction RR_FMI3_NAME(fmi3SetIntervalFraction)
#define fmi3SetShiftDecimal RR_FMI3_NAME(fmi3SetShiftDecimal)
#define fmi3SetShiftFraction RR_FMI3_NAME(fmi3SetShiftFraction)
#define fmi3EvaluateDiscreteStates RR_FMI3_NAME(fmi3EvaluateDiscreteStates)
#define fmi3UpdateDiscreteStates RR_FMI3_NAME(fmi3UpdateDiscreteStates)
#define fmi3EnterContinuousTimeMode RR_FMI3_NAME(fmi3EnterContinuousTimeMode)
#define fmi3CompletedIntegratorStep RR_FMI3_NAME(fmi3CompletedIntegratorStep)
#define fmi3SetTime RR_FMI3_NAME(fmi3SetTime)
#define fmi3SetContinuousStates RR_FMI3_NAME(fmi3SetContinuousStates)
#define fmi3GetContinuousStateDerivatives RR_FMI3_NAME(fmi3GetContinuousStateDerivatives)
#define fmi3GetEventIndicators RR_FMI3_NAME(fmi3GetEventIndicators)
#define fmi3GetContinuousStates RR_FMI3_NAME(fmi3GetContinuousStates)
#define fmi3GetNominalsOfContinuousStates RR_FMI3_NAME(fmi3GetNominalsOfContinuousStates)
#define fmi3GetNumberOfEventIndicators RR_FMI3_NAME(fmi3GetNumberOfEventIndicators)
#define fmi3GetNumberOfContinuousStates RR_FMI3_NAME(fmi3GetNumberOfContinuousStates)
#define fmi3EnterStepMode RR_FMI3_NAME(fmi3EnterStepMode)
#define fmi3GetOutputDerivatives RR_FMI3_NAME(fmi3GetOutputDerivatives)
#define fmi3DoStep RR_FMI3_NAME(fmi3DoStep)
#define fmi3ActivateModelPartition RR_FMI3_NAME(fmi3ActivateModelPartition)
#endif

/* platform types */
typedef void *fmi3Instance;
typedef void *fmi3InstanceEnvironment;
typedef void *fmi3FMUState;
typedef uint32_t fmi3ValueReference;
typedef float fmi3Float32;
typedef double fmi3Float64;
typedef int8_t fmi3Int8;
typedef uint8_t fmi3UInt8;
typedef int16_t fmi3Int16;
typedef uint16_t fmi3UInt16;
typedef int32_t fmi3Int32;
typedef uint32_t fmi3UInt32;
typedef int64_t fmi3Int64;
typedef uint64_t fmi3UInt64;
typedef bool fmi3Boolean;
typedef char fmi3Char;
typedef const fmi3Char *fmi3String;
typedef uint8_t fmi3Byte;
typedef const fmi3Byte *fmi3Binary;
typedef bool fmi3Clock;

#define fmi3True true
#define fmi3False false

typedef enum { fmi3OK, fmi3Warning, fmi3Discard, fmi3Error, fmi3Fatal } fmi3Status;
typedef enum {
    fmi3Independent, fmi3Constant, fmi3Fixed, fmi3Tunable, fmi3Discrete, fmi3Dependent
} fmi3DependencyKind;
typedef enum {
    fmi3IntervalNotYetKnown, fmi3IntervalUnchanged, fmi3IntervalChanged
} fmi3IntervalQualifier;

/* the importer's callbacks */
typedef void (*fmi3LogMessageCallback)(fmi3InstanceEnvironment instanceEnvironment,
                                       fmi3Status status, fmi3String category,
                                       fmi3String message);
typedef void (*fmi3ClockUpdateCallback)(fmi3InstanceEnvironment instanceEnvironment);
typedef void (*fmi3IntermediateUpdateCallback)(
    fmi3InstanceEnvironment instanceEnvironment, fmi3Float64 intermediateUpdateTime,
    fmi3Boolean intermediateVariableSetRequested, fmi3Boolean intermediateVariableGetAllowed,
    fmi3Boolean intermediateStepFinished, fmi3Boolean canReturnEarly,
    fmi3Boolean *earlyReturnRequested, fmi3Float64 *earlyReturnTime);
typedef void (*fmi3LockPreemptionCallback)(void);
typedef void (*fmi3UnlockPreemptionCallback)(void);

#define RR_FMI3_VRS fmi3Instance instance, const fmi3ValueReference valueReferences[], \
    size_t nValueReferences

/* inquiry, logging, instances */
RR_FMI3_EXPORT const char *fmi3GetVersion(void);
RR_FMI3_EXPORT fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn,
                                              size_t nCategories,
                                              const fmi3String categories[]);
RR_FMI3_EXPORT fmi3Instance fmi3InstantiateModelExchange(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage);
RR_FMI3_EXPORT fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3IntermediateUpdateCallback intermediateUpdate);
RR_FMI3_EXPORT fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
    fmi3LockPreemptionCallback lockPreemption, fmi3UnlockPreemptionCallback unlockPreemption);
RR_FMI3_EXPORT void fmi3FreeInstance(fmi3Instance instance);

/* the modes */
RR_FMI3_EXPORT fmi3Status fmi3EnterInitializationMode(fmi3Instance instance,
                                                      fmi3Boolean toleranceDefined,
                                                      fmi3Float64 tolerance,
                                                      fmi3Float64 startTime,
                                                      fmi3Boolean stopTimeDefined,
                                                      fmi3Float64 stopTime);
RR_FMI3_EXPORT fmi3Status fmi3ExitInitializationMode(fmi3Instance instance);
RR_FMI3_EXPORT fmi3Status fmi3EnterEventMode(fmi3Instance instance);
RR_FMI3_EXPORT fmi3Status fmi3Terminate(fmi3Instance instance);
RR_FMI3_EXPORT fmi3Status fmi3Reset(fmi3Instance instance);

/* values: fmi3Get<Type>, fmi3Set<Type> for every type */
#define RR_FMI3_GET_SET(T, Name)                                                         \
    RR_FMI3_EXPORT fmi3Status fmi3Get##Name(RR_FMI3_VRS, T values[], size_t nValues);   \
    RR_FMI3_EXPORT fmi3Status fmi3Set##Name(RR_FMI3_VRS, const T values[], size_t nValues);
RR_FMI3_GET_SET(fmi3Float32, Float32)
RR_FMI3_GET_SET(fmi3Float64, Float64)
RR_FMI3_GET_SET(fmi3Int8, Int8)
RR_FMI3_GET_SET(fmi3UInt8, UInt8)
RR_FMI3_GET_SET(fmi3Int16, Int16)
RR_FMI3_GET_SET(fmi3UInt16, UInt16)
RR_FMI3_GET_SET(fmi3Int32, Int32)
RR_FMI3_GET_SET(fmi3UInt32, UInt32)
RR_FMI3_GET_SET(fmi3Int64, Int64)
RR_FMI3_GET_SET(fmi3UInt64, UInt64)
RR_FMI3_GET_SET(fmi3Boolean, Boolean)
RR_FMI3_GET_SET(fmi3String, String)
RR_FMI3_EXPORT fmi3Status fmi3GetBinary(RR_FMI3_VRS, size_t valueSizes[], fmi3Binary values[],
                                        size_t nValues);
RR_FMI3_EXPORT fmi3Status fmi3SetBinary(RR_FMI3_VRS, const size_t valueSizes[],
                                        const fmi3Binary values[], size_t nValues);
RR_FMI3_EXPORT fmi3Status fmi3GetClock(RR_FMI3_VRS, fmi3Clock values[]);
RR_FMI3_EXPORT fmi3Status fmi3SetClock(RR_FMI3_VRS, const fmi3Clock values[]);

/* dependencies */
RR_FMI3_EXPORT fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance,
                                                              fmi3ValueReference valueReference,
                                                              size_t *nDependencies);
RR_FMI3_EXPORT fmi3Status fmi3GetVariableDependencies(
    fmi3Instance instance, fmi3ValueReference dependent, size_t elementIndicesOfDependent[],
    fmi3ValueReference independents[], size_t elementIndicesOfIndependents[],
    fmi3DependencyKind dependencyKinds[], size_t nDependencies);

/* FMU states */
RR_FMI3_EXPORT fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState *FMUState);
RR_FMI3_EXPORT fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState);
RR_FMI3_EXPORT fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState *FMUState);
RR_FMI3_EXPORT fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance,
                                                     fmi3FMUState FMUState, size_t *size);
RR_FMI3_EXPORT fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState,
                                                fmi3Byte serializedState[], size_t size);
RR_FMI3_EXPORT fmi3Status fmi3DeserializeFMUState(fmi3Instance instance,
                                                  const fmi3Byte serializedState[],
                                                  size_t size, fmi3FMUState *FMUState);

/* derivatives */
RR_FMI3_EXPORT fmi3Status fmi3GetDirectionalDerivative(
    fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
    fmi3Float64 sensitivity[], size_t nSensitivity);
RR_FMI3_EXPORT fmi3Status fmi3GetAdjointDerivative(
    fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
    fmi3Float64 sensitivity[], size_t nSensitivity);

/* configuration mode, clocks, discrete states */
RR_FMI3_EXPORT fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance);
RR_FMI3_EXPORT fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance);
RR_FMI3_EXPORT fmi3Status fmi3GetIntervalDecimal(RR_FMI3_VRS, fmi3Float64 intervals[],
                                                 fmi3IntervalQualifier qualifiers[]);
RR_FMI3_EXPORT fmi3Status fmi3GetIntervalFraction(RR_FMI3_VRS, fmi3UInt64 counters[],
                                                  fmi3UInt64 resolutions[],
                                                  fmi3IntervalQualifier qualifiers[]);
RR_FMI3_EXPORT fmi3Status fmi3GetShiftDecimal(RR_FMI3_VRS, fmi3Float64 shifts[]);
RR_FMI3_EXPORT fmi3Status fmi3GetShiftFraction(RR_FMI3_VRS, fmi3UInt64 counters[],
                                               fmi3UInt64 resolutions[]);
RR_FMI3_EXPORT fmi3Status fmi3SetIntervalDecimal(RR_FMI3_VRS, const fmi3Float64 intervals[]);
RR_FMI3_EXPORT fmi3Status fmi3SetIntervalFraction(RR_FMI3_VRS, const fmi3UInt64 counters[],
                                                  const fmi3UInt64 resolutions[]);
RR_FMI3_EXPORT fmi3Status fmi3SetShiftDecimal(RR_FMI3_VRS, const fmi3Float64 shifts[]);
RR_FMI3_EXPORT fmi3Status fmi3SetShiftFraction(RR_FMI3_VRS, const fmi3UInt64 counters[],
                                               const fmi3UInt64 resolutions[]);
RR_FMI3_EXPORT fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance);
RR_FMI3_EXPORT fmi3Status fmi3UpdateDiscreteStates(
    fmi3Instance instance, fmi3Boolean *discreteStatesNeedUpdate,
    fmi3Boolean *terminateSimulation, fmi3Boolean *nominalsOfContinuousStatesChanged,
    fmi3Boolean *valuesOfContinuousStatesChanged, fmi3Boolean *nextEventTimeDefined,
    fmi3Float64 *nextEventTime);

/* model exchange */
RR_FMI3_EXPORT fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance);
RR_FMI3_EXPORT fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance,
                                                      fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                                      fmi3Boolean *enterEventMode,
                                                      fmi3Boolean *terminateSimulation);
RR_FMI3_EXPORT fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time);
RR_FMI3_EXPORT fmi3Status fmi3SetContinuousStates(fmi3Instance instance,
                                                  const fmi3Float64 continuousStates[],
                                                  size_t nContinuousStates);
RR_FMI3_EXPORT fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance,
                                                            fmi3Float64 derivatives[],
                                                            size_t nContinuousStates);
RR_FMI3_EXPORT fmi3Status fmi3GetEventIndicators(fmi3Instance instance,
                                                 fmi3Float64 eventIndicators[],
                                                 size_t nEventIndicators);
RR_FMI3_EXPORT fmi3Status fmi3GetContinuousStates(fmi3Instance instance,
                                                  fmi3Float64 continuousStates[],
                                                  size_t nContinuousStates);
RR_FMI3_EXPORT fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance,
                                                            fmi3Float64 nominals[],
                                                            size_t nContinuousStates);
RR_FMI3_EXPORT fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance,
                                                         size_t *nEventIndicators);
RR_FMI3_EXPORT fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance,
                                                          size_t *nContinuousStates);

/* co-simulation */
RR_FMI3_EXPORT fmi3Status fmi3EnterStepMode(fmi3Instance instance);
RR_FMI3_EXPORT fmi3Status fmi3GetOutputDerivatives(RR_FMI3_VRS, const fmi3Int32 orders[],
                                                   fmi3Float64 values[], size_t nValues);
RR_FMI3_EXPORT fmi3Status fmi3DoStep(fmi3Instance instance,
                                     fmi3Float64 currentCommunicationPoint,
                                     fmi3Float64 communicationStepSize,
                                     fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                     fmi3Boolean *eventHandlingNeeded,
                                     fmi3Boolean *terminateSimulation,
                                     fmi3Boolean *earlyReturn,
                                     fmi3Float64 *lastSuccessfulTime);

/* scheduled execution */
RR_FMI3_EXPORT fmi3Status fmi3ActivateModelPartition(fmi3Instance instance,
                                                     fmi3ValueReference clockReference,
                                                     fmi3Float64 activationTime);

#endif
