/*
 * rig_paper.c - the seed paper's scenario on the default rig, from C alone:
 * the parameters of rr_rig_params.h's declaration (rr_rig_config_default),
 * the contact table of rr_rig_table_build, the references of
 * rr_rig_schedule; every sample's record (RR_REC_COUNT doubles) is written
 * to stdout as raw native doubles, the records of rollerrig.simulate() bit
 * for bit (tests/test_rig_c_program.py).
 *
 *   make -C csrc paper            # builds csrc/build/rig_paper
 *   csrc/build/rig_paper > records.f64
 *
 * Exit status 0, or 1 with a message on stderr if a step fails.
 */
#include <stdio.h>
#include <stdlib.h>

#include "rollerrig.h"

int main(void)
{
    static double work[RR_RIG_TABLE_WORK_LEN];
    static rr_rig rig;
    rr_rig_config c;
    rr_rig_geometry g;
    rr_contact_table t;
    rr_rig_params p;
    double rec[RR_REC_COUNT], *data, *rig_work = NULL, roller_ref, xi_ref;
    size_t nwork = 0;
    long k, n, len;
    int st;

    rr_rig_config_default(&c);
    rr_rig_geometry_from(&c, &g);
    len = rr_rig_table_data_len(&g);
    if (!(data = malloc((size_t)len * sizeof *data))) {
        fprintf(stderr, "rig_paper: out of memory\n");
        return 1;
    }
    if ((st = rr_rig_table_build(&g, data, len, work, RR_RIG_TABLE_WORK_LEN, &t, NULL)) >= 0
        && (st = rr_rig_params_from(&c, &t, &p)) >= 0) {
        /* the creep method's workspace is the caller's, allocated before the
         * run (none for the methods the rig steps with today) */
        nwork = rr_rig_workspace_len(&p);
        if (nwork > 0 && !(rig_work = malloc(nwork * sizeof *rig_work)))
            st = RR_ERR_WORKSPACE;
    }
    if (st < 0 || (st = rr_rig_init(&p, c.roller_speed / c.roller_radius, rig_work, nwork,
                                    &rig)) < 0) {
        fprintf(stderr, "rig_paper: %s\n", rr_status_message(st));
        free(rig_work);
        free(data);
        return 1;
    }
    n = rr_rig_samples(&c);
    for (k = 0; k < n; k++) {
        rr_rig_schedule(&c, k, &roller_ref, &xi_ref);
        st = rr_rig_step(&rig, roller_ref, xi_ref, rec);
        if (st < 0) {
            fprintf(stderr, "rig_paper: sample %ld: %s\n", k, rr_status_message(st));
            free(rig_work);
            free(data);
            return 1;
        }
        if (fwrite(rec, sizeof rec[0], RR_REC_COUNT, stdout) != RR_REC_COUNT) {
            fprintf(stderr, "rig_paper: cannot write the records\n");
            free(rig_work);
            free(data);
            return 1;
        }
    }
    free(rig_work);
    free(data);
    return 0;
}
