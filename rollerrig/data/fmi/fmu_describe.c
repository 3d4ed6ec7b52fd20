/*
 * fmu_describe.c - a build tool of `rollerrig fmu` (not part of an FMU):
 * prints the modelDescription.xml of the FMU being built, from the unit's
 * variables (csrc/fmu/rr_fmu_xml.h) at the FMU's start values
 * (fmu_start.c, generated).
 *
 *   fmu_describe VERSION MODEL_IDENTIFIER MODEL_NAME GENERATION_TOOL DESCRIPTION [SOURCE...]
 *
 * VERSION 2 or 3; SOURCE: the C files of sources/, listed in an FMI 2.0
 * description.  Exit status 0, or 1 with a message on stderr.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util/rr_common.h"
#include "fmu/rr_fmu_xml.h"
#include "fmu_build.h"

int main(int argc, char **argv)
{
    rr_fmu_config start;
    rr_fmu_xml_info info;
    long n;
    char *buf;
    int st;

    if (argc < 6 || (strcmp(argv[1], "2") != 0 && strcmp(argv[1], "3") != 0)) {
        fprintf(stderr, "usage: fmu_describe 2|3 MODEL_IDENTIFIER MODEL_NAME GENERATION_TOOL "
                "DESCRIPTION [SOURCE...]\n");
        return 1;
    }
    if ((st = rr_fmu_start_config(&start)) != RR_OK) {
        fprintf(stderr, "fmu_describe: the start values are refused: %s\n",
                rr_status_message(st));
        return 1;
    }
    info.fmi_version = atoi(argv[1]);
    info.model_identifier = argv[2];
    info.model_name = argv[3];
    info.generation_tool = argv[4];
    info.description = argv[5];
    info.token = rr_fmu_token;
    info.sources = (const char *const *)(argv + 6);
    info.nsources = argc - 6;
    n = rr_fmu_xml(&info, &start, NULL, 0);
    if (n < 0 || !(buf = malloc((size_t)n + 1))) {
        fprintf(stderr, "fmu_describe: %s\n", n < 0 ? rr_status_message((int)n) : "out of memory");
        return 1;
    }
    rr_fmu_xml(&info, &start, buf, n + 1);
    st = fwrite(buf, 1, (size_t)n, stdout) == (size_t)n ? 0 : 1;
    free(buf);
    return st;
}
