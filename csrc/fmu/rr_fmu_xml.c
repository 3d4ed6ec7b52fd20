/* rr_fmu_xml.c - the modelDescription.xml of the rig's co-simulation unit (rr_fmu_xml.h). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "util/rr_common.h"
#include "fmu/rr_fmu_xml.h"

/* An appender: writes what fits, counts everything. */
typedef struct {
    char *buf;
    long len, pos;
} out;

static void put(out *o, const char *fmt, ...)
{
    va_list ap;
    char *at = o->buf && o->pos < o->len ? o->buf + o->pos : NULL;
    size_t room = at ? (size_t)(o->len - o->pos) : 0;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(at, room, fmt, ap);
    va_end(ap);
    if (n > 0)
        o->pos += n;
}

/* text with &, <, >, " escaped, as an attribute's value */
static void put_text(out *o, const char *s)
{
    for (; s && *s; s++) {
        switch (*s) {
        case '&':
            put(o, "&amp;");
            break;
        case '<':
            put(o, "&lt;");
            break;
        case '>':
            put(o, "&gt;");
            break;
        case '"':
            put(o, "&quot;");
            break;
        default:
            put(o, "%c", *s);
        }
    }
}

static void put_attr(out *o, const char *name, const char *value)
{
    put(o, " %s=\"", name);
    put_text(o, value);
    put(o, "\"");
}

static void put_num(out *o, const char *name, double x)
{
    char num[32];
    rr_fmu_format_number(x, num, sizeof num);
    put(o, " %s=\"%s\"", name, num);
}

/* ------------------------------------------------------------------ units */

static int symbol(const char *s, size_t n, int e[4], int sign)
{
    static const struct {
        const char *name;
        int e[4];            /* kg, m, s, rad */
    } symbols[] = {
        {"kg", {1, 0, 0, 0}}, {"m", {0, 1, 0, 0}}, {"s", {0, 0, 1, 0}},
        {"rad", {0, 0, 0, 1}}, {"N", {1, 1, -2, 0}}, {"Pa", {1, -1, -2, 0}},
        {"1", {0, 0, 0, 0}},                         /* dimensionless (CF, UDUNITS) */
    };
    size_t len = n;
    int power = 1, i, j;
    const char *caret = memchr(s, '^', n);
    if (caret) {
        len = (size_t)(caret - s);
        power = 0;
        for (j = 1; caret + j < s + n; j++) {
            if (caret[j] < '0' || caret[j] > '9')
                return 0;
            power = 10 * power + (caret[j] - '0');
        }
        if (j == 1)
            return 0;
    }
    for (i = 0; i < (int)(sizeof symbols / sizeof symbols[0]); i++)
        if (strlen(symbols[i].name) == len && strncmp(symbols[i].name, s, len) == 0) {
            for (j = 0; j < 4; j++)
                e[j] += sign * power * symbols[i].e[j];
            return 1;
        }
    return 0;
}

int rr_fmu_unit_base(const char *unit, int e[4])
{
    const char *s = unit;
    int sign = 1, j;
    if (!unit || !e)
        return 0;
    for (j = 0; j < 4; j++)
        e[j] = 0;
    while (*s) {
        size_t n = strcspn(s, " /");
        if (n > 0 && !symbol(s, n, e, sign))
            return 0;
        s += n;
        if (*s == '/') {
            if (sign < 0)
                return 0;
            sign = -1;
        }
        if (*s)
            s++;
    }
    return 1;
}

/* The unit the description gives v: its declaration's in the CF / UDUNITS
 * spelling the package writes (rollerrig/_units.py: the C tables' "-",
 * dimensionless, is "1"), or NULL: none for a name, a flag, a choice or an
 * integer (FMI gives units to reals only). */
static const char *xml_unit(const rr_fmu_var *v)
{
    if (v->type != RR_FMU_REAL || !v->unit[0])
        return NULL;
    return strcmp(v->unit, "-") == 0 ? "1" : v->unit;
}

static void unit_definitions(out *o, const rr_fmu_config *start)
{
    static const char *const base[4] = {"kg", "m", "s", "rad"};
    const int n = rr_fmu_var_count(start);
    int i, j, k;
    put(o, "  <UnitDefinitions>\n");
    for (i = 0; i < n; i++) {
        rr_fmu_var v, w;
        int e[4], seen = 0;
        const char *unit, *other;
        rr_fmu_var_at(start, i, &v);
        if ((unit = xml_unit(&v)) == NULL)
            continue;
        for (j = 0; j < i && !seen; j++) {
            rr_fmu_var_at(start, j, &w);
            seen = (other = xml_unit(&w)) != NULL && strcmp(other, unit) == 0;
        }
        if (seen)
            continue;
        put(o, "    <Unit");
        put_attr(o, "name", unit);
        if (rr_fmu_unit_base(unit, e)) {
            put(o, ">\n      <BaseUnit");
            for (k = 0; k < 4; k++)
                if (e[k])
                    put(o, " %s=\"%d\"", base[k], e[k]);
            put(o, "/>\n    </Unit>\n");
        } else {
            put(o, "/>\n");
        }
    }
    put(o, "  </UnitDefinitions>\n");
}

/* ------------------------------------------------------------------ types */

static void type_definitions(out *o, const rr_fmu_config *start, int fmi)
{
    const int n = rr_fmu_var_count(start);
    int i, k, value;
    const char *name;
    put(o, "  <TypeDefinitions>\n");
    for (i = 0; i < n; i++) {
        rr_fmu_var v;
        char vname[RR_FMU_NAME_LEN];
        rr_fmu_var_at(start, i, &v);
        if (v.type != RR_FMU_ENUMERATION)
            continue;
        rr_fmu_var_name(&v, vname, sizeof vname);
        if (fmi == 2) {
            put(o, "    <SimpleType");
            put_attr(o, "name", vname);
            put(o, ">\n      <Enumeration>\n");
        } else {
            put(o, "    <EnumerationType");
            put_attr(o, "name", vname);
            put(o, ">\n");
        }
        for (k = 0; rr_fmu_var_item(&v, k, &name, &value); k++) {
            put(o, fmi == 2 ? "        <Item" : "      <Item");
            put_attr(o, "name", name);
            put(o, " value=\"%d\"/>\n", value);
        }
        put(o, fmi == 2 ? "      </Enumeration>\n    </SimpleType>\n" : "    </EnumerationType>\n");
    }
    put(o, "  </TypeDefinitions>\n");
}

/* ------------------------------------------------------------------ variables */

static const char *const causality_names[] = {"independent", "parameter", "input", "output"};
static const char *const variability_names[] = {"continuous", "discrete", "fixed", "tunable"};

/* min, max (finite ends only), start */
static void put_values(out *o, const rr_fmu_config *start, const rr_fmu_var *v)
{
    double x;
    if (v->type == RR_FMU_REAL || v->type == RR_FMU_INTEGER) {
        if (isfinite(v->lo))
            put_num(o, "min", v->lo);
        if (isfinite(v->hi))
            put_num(o, "max", v->hi);
    }
    if (rr_fmu_var_start(start, v, &x) != RR_OK)
        return;
    if (v->type == RR_FMU_BOOLEAN)
        put(o, " start=\"%s\"", x != 0.0 ? "true" : "false");
    else if (v->type == RR_FMU_REAL)
        put_num(o, "start", x);
    else
        put(o, " start=\"%ld\"", (long)x);
}

/* What FMI 2.0's ScalarVariable and 3.0's typed element share: name, value
 * reference, description, causality, variability, initial. */
static void put_identity(out *o, const rr_fmu_var *v, const char *name)
{
    put_attr(o, "name", name);
    put(o, " valueReference=\"%u\"", v->vr);
    if (v->description[0])
        put_attr(o, "description", v->description);
    put(o, " causality=\"%s\" variability=\"%s\"", causality_names[v->causality],
        variability_names[v->variability]);
    if (v->causality == RR_FMU_OUTPUT)
        put(o, " initial=\"calculated\"");
}

/* ... and the type's attributes: declared type, unit, start, range. */
static void put_type(out *o, const rr_fmu_config *start, const rr_fmu_var *v, const char *name)
{
    if (v->type == RR_FMU_ENUMERATION)
        put_attr(o, "declaredType", name);
    if (xml_unit(v))
        put_attr(o, "unit", xml_unit(v));
    put_values(o, start, v);
}

static void variable2(out *o, const rr_fmu_config *start, const rr_fmu_var *v)
{
    static const char *const elements[] = {"Real", "Integer", "Boolean", "Enumeration"};
    char name[RR_FMU_NAME_LEN];
    rr_fmu_var_name(v, name, sizeof name);
    put(o, "    <ScalarVariable");
    put_identity(o, v, name);
    put(o, ">\n      <%s", elements[v->type]);
    put_type(o, start, v, name);
    put(o, "/>\n    </ScalarVariable>\n");
}

static void variable3(out *o, const rr_fmu_config *start, const rr_fmu_var *v)
{
    static const char *const elements[] = {"Float64", "Int32", "Boolean", "Enumeration"};
    char name[RR_FMU_NAME_LEN];
    rr_fmu_var_name(v, name, sizeof name);
    put(o, "    <%s", elements[v->type]);
    put_identity(o, v, name);
    put_type(o, start, v, name);
    put(o, "/>\n");
}

static void model_structure(out *o, const rr_fmu_config *start, int fmi)
{
    const int n = rr_fmu_var_count(start);
    int pass, i;
    put(o, "  <ModelStructure>\n");
    /* the outputs, then the same as initial unknowns */
    for (pass = 0; pass < 2; pass++) {
        if (fmi == 2)
            put(o, pass ? "    <InitialUnknowns>\n" : "    <Outputs>\n");
        for (i = 0; i < n; i++) {
            rr_fmu_var v;
            rr_fmu_var_at(start, i, &v);
            if (v.causality != RR_FMU_OUTPUT)
                continue;
            if (fmi == 2)
                put(o, "      <Unknown index=\"%d\"/>\n", i + 1);
            else
                put(o, "    <%s valueReference=\"%u\"/>\n", pass ? "InitialUnknown" : "Output",
                    v.vr);
        }
        if (fmi == 2)
            put(o, pass ? "    </InitialUnknowns>\n" : "    </Outputs>\n");
    }
    put(o, "  </ModelStructure>\n");
}

long rr_fmu_xml(const rr_fmu_xml_info *info, const rr_fmu_config *start, char *buf, long len)
{
    out o;
    const int fmi = info ? info->fmi_version : 0;
    int i, n;
    double T, duration;
    if (!info || !start || !info->model_identifier || !info->model_name || !info->description
        || !info->generation_tool || !info->token || (info->nsources > 0 && !info->sources))
        return RR_ERR_NULL;
    if (fmi != 2 && fmi != 3)
        return RR_ERR_PARAM;
    o.buf = len > 0 ? buf : NULL;
    o.len = o.buf ? len : 0;
    o.pos = 0;
    if (o.buf)
        o.buf[0] = '\0';
    T = start->c.T;
    duration = start->c.duration;

    put(&o, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<fmiModelDescription\n");
    put(&o, "  fmiVersion=\"%s\"\n ", fmi == 2 ? "2.0" : "3.0");
    put_attr(&o, "modelName", info->model_name);
    put(&o, "\n ");
    put_attr(&o, "description", info->description);
    put(&o, "\n ");
    put_attr(&o, "generationTool", info->generation_tool);
    put(&o, "\n ");
    put_attr(&o, fmi == 2 ? "guid" : "instantiationToken", info->token);
    put(&o, "\n  variableNamingConvention=\"structured\"");
    if (fmi == 2)
        put(&o, "\n  numberOfEventIndicators=\"0\"");
    put(&o, ">\n\n  <CoSimulation\n   ");
    put_attr(&o, "modelIdentifier", info->model_identifier);
    if (fmi == 2) {
        put(&o, "\n    needsExecutionTool=\"false\"\n"
            "    canHandleVariableCommunicationStepSize=\"true\"\n"
            "    canInterpolateInputs=\"false\"\n"
            "    maxOutputDerivativeOrder=\"0\"\n"
            "    canRunAsynchronuously=\"false\"\n"
            "    canBeInstantiatedOnlyOncePerProcess=\"false\"\n"
            "    canNotUseMemoryManagementFunctions=\"true\"\n"
            "    canGetAndSetFMUstate=\"true\"\n"
            "    canSerializeFMUstate=\"true\"\n"
            "    providesDirectionalDerivative=\"false\"");
        if (info->nsources > 0) {
            put(&o, ">\n    <SourceFiles>\n");
            for (i = 0; i < info->nsources; i++) {
                put(&o, "      <File");
                put_attr(&o, "name", info->sources[i]);
                put(&o, "/>\n");
            }
            put(&o, "    </SourceFiles>\n  </CoSimulation>\n\n");
        } else {
            put(&o, "/>\n\n");
        }
    } else {
        put(&o, "\n    canHandleVariableCommunicationStepSize=\"true\"\n");
        put(&o, "   ");
        put_num(&o, "fixedInternalStepSize", T);
        put(&o, "\n    canGetAndSetFMUState=\"true\"\n"
            "    canSerializeFMUState=\"true\"\n"
            "    hasEventMode=\"false\"\n"
            "    providesIntermediateUpdate=\"false\"\n"
            "    mightReturnEarlyFromDoStep=\"false\"/>\n\n");
    }
    unit_definitions(&o, start);
    put(&o, "\n");
    type_definitions(&o, start, fmi);
    put(&o, "\n  <LogCategories>\n"
        "    <Category name=\"logEvents\" description=\"the unit's life: initialization, the "
        "contact table, reset, FMU states\"/>\n"
        "    <Category name=\"logStatusWarning\" description=\"warnings: a sample whose "
        "integrator stage was left off\"/>\n"
        "    <Category name=\"logStatusError\" description=\"errors: a refused value or call, "
        "a sample that failed\"/>\n"
        "  </LogCategories>\n\n");
    put(&o, "  <DefaultExperiment startTime=\"0\"");
    put_num(&o, "stopTime", duration);
    put_num(&o, "stepSize", T);
    put(&o, "/>\n\n  <ModelVariables>\n");
    n = rr_fmu_var_count(start);
    for (i = 0; i < n; i++) {
        rr_fmu_var v;
        rr_fmu_var_at(start, i, &v);
        if (fmi == 2)
            variable2(&o, start, &v);
        else
            variable3(&o, start, &v);
    }
    put(&o, "  </ModelVariables>\n\n");
    model_structure(&o, start, fmi);
    put(&o, "\n</fmiModelDescription>\n");
    return o.pos;
}
