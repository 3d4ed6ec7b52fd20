/*
 * rig_paper.c - the seed paper's scenario on the default rig, from C alone:
 * the parameters of rr_rig_params.h's declaration (rr_rig_config_default),
 * the contact table of rr_rig_table_build, the references of
 * rr_rig_schedule; every sample's record (RR_REC_COUNT doubles) is written
 * to stdout as raw native doubles, the records of rollerrig.simulate() bit
 * for bit (tests/test_rig_c_program.py).
 *
 * On real profiles: give the profiles' points as files (two numbers a line,
 * y and z in metres, full size, referenced as rollerrig.rig.real_profiles
 * reads them: rollerrig.rig.build.write_points writes them; a line
 * "# end natural" for a smoothed profile's end condition), and the values
 * that differ from the defaults:
 *
 *   rig_paper [-s section.key=value]... [wheel=FILE] [roller=FILE]
 *             [wheel_right=FILE] [roller_right=FILE]
 *
 * A file given sets its row ("wheelset.profile", ...) to "points"; the
 * table is rr_rig_table_build_profiles' (tests/test_rig_profiles_c.py: the
 * records of rollerrig.simulate() on the same scenario, bit for bit).
 *
 * On the non-Hertzian contact (-s contact.patch=nonhertz) give its two
 * tables as files (nonhertz_left=FILE nonhertz_right=FILE; write_points
 * writes them from the table rollerrig builds or reads: a line of sigma,
 * R0, G, nu, mu_ref and the row count, then the rows, RR_NH_ROW_LEN
 * numbers each, every digit; '#' lines are comments):
 * rr_rig_params_set_nonhertz, checked at rr_rig_init (tests/test_rig_nonhertz_c.py).
 *
 *   make -C csrc paper            # builds csrc/build/rig_paper
 *   csrc/build/rig_paper > records.f64
 *
 * Exit status 0, 1 with a message on stderr if a step fails, 2 for bad
 * arguments or files.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rollerrig.h"

#define MAX_POINTS 20000

static const char *const slot_names[] = {"wheel", "roller", "wheel_right", "roller_right"};
static const char *const slot_rows[] = {"wheelset.profile", "roller.profile",
                                        "wheelset.profile_right", "roller.profile_right"};
static const char *const nonhertz_names[] = {"nonhertz_left", "nonhertz_right"};

/* A points file into p (arrays malloc'ed); 0, or -1 with a message. */
static int read_points(const char *path, rr_profile_points *p)
{
    FILE *f = fopen(path, "r");
    char line[256];
    double *y = malloc(MAX_POINTS * sizeof *y), *z = malloc(MAX_POINTS * sizeof *z);
    int n = 0, row = 0;
    p->end = RR_SPLINE_NOT_A_KNOT;
    if (!f || !y || !z) {
        fprintf(stderr, "rig_paper: %s: %s\n", path, f ? "out of memory" : "cannot open it");
        goto fail;
    }
    while (fgets(line, sizeof line, f)) {
        row++;
        if (line[0] == '#') {
            if (strstr(line, "end natural"))
                p->end = RR_SPLINE_NATURAL;
            continue;
        }
        if (n == MAX_POINTS || sscanf(line, "%lf %lf", &y[n], &z[n]) != 2) {
            fprintf(stderr, "rig_paper: %s: line %d: %s\n", path, row,
                    n == MAX_POINTS ? "too many points" : "expected two numbers 'y z'");
            goto fail;
        }
        n++;
    }
    fclose(f);
    p->n = n;
    p->y = y;
    p->z = z;
    return 0;
fail:
    if (f)
        fclose(f);
    free(y);
    free(z);
    return -1;
}

/* A non-Hertzian table file into t (its rows malloc'ed); 0, or -1 with a
 * message (the table's own checks are rr_rig_init's). */
static int read_nonhertz(const char *path, rr_nh_table *t)
{
    FILE *f = fopen(path, "r");
    double nrows = 0.0, *rows = NULL;
    long i, n;
    int ch;
    if (!f) {
        fprintf(stderr, "rig_paper: %s: cannot open it\n", path);
        return -1;
    }
    while ((ch = fgetc(f)) == '#')           /* comment lines */
        while ((ch = fgetc(f)) != EOF && ch != '\n')
            ;
    if (ch != EOF)
        ungetc(ch, f);
    if (fscanf(f, "%lf %lf %lf %lf %lf %lf", &t->sigma, &t->R0, &t->G, &t->nu, &t->mu_ref,
               &nrows) != 6 || !(nrows >= 2.0 && nrows <= 1e6) || nrows != (long)nrows) {
        fprintf(stderr, "rig_paper: %s: expected 'sigma R0 G nu mu_ref rows' first\n", path);
        fclose(f);
        return -1;
    }
    n = (long)nrows * RR_NH_ROW_LEN;
    if (!(rows = malloc((size_t)n * sizeof *rows))) {
        fprintf(stderr, "rig_paper: %s: out of memory\n", path);
        fclose(f);
        return -1;
    }
    for (i = 0; i < n; i++)
        if (fscanf(f, "%lf", &rows[i]) != 1) {
            fprintf(stderr, "rig_paper: %s: row %ld: expected %d numbers a row\n", path,
                    i / RR_NH_ROW_LEN, RR_NH_ROW_LEN);
            free(rows);
            fclose(f);
            return -1;
        }
    fclose(f);
    t->nrows = (int)nrows;
    t->rows = rows;
    return 0;
}

/* The arguments into the configuration, the profiles and the non-Hertzian
 * tables; 0, or -1. */
static int parse_args(int argc, char **argv, rr_rig_config *c, rr_rig_profiles *given,
                      rr_nh_table nh[2])
{
    int i, k;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *eq = strchr(a, '=');
        if (strcmp(a, "-s") == 0 && i + 1 < argc) {
            char name[128];
            const char *v = argv[++i], *e = strchr(v, '=');
            char *end;
            double x;
            if (!e || (size_t)(e - v) >= sizeof name) {
                fprintf(stderr, "rig_paper: -s %s: expected section.key=value\n", v);
                return -1;
            }
            memcpy(name, v, (size_t)(e - v));
            name[e - v] = '\0';
            x = strtod(e + 1, &end);
            if ((*end != '\0' ? rr_rig_config_set_choice(c, name, e + 1)
                              : rr_rig_config_set(c, name, x)) < 0) {
                fprintf(stderr, "rig_paper: -s %s: refused\n", v);
                return -1;
            }
            continue;
        }
        for (k = 0; k < 2 && eq; k++)
            if (strlen(nonhertz_names[k]) == (size_t)(eq - a)
                && strncmp(a, nonhertz_names[k], (size_t)(eq - a)) == 0)
                break;
        if (eq && k < 2) {
            if (nh[k].rows || read_nonhertz(eq + 1, &nh[k]) < 0)
                return -1;
            continue;
        }
        for (k = 0; k < 4 && eq; k++)
            if (strlen(slot_names[k]) == (size_t)(eq - a)
                && strncmp(a, slot_names[k], (size_t)(eq - a)) == 0)
                break;
        if (!eq || k == 4) {
            fprintf(stderr, "rig_paper: unknown argument %s\n", a);
            return -1;
        }
        if (rr_rig_config_set_choice(c, slot_rows[k], "points") < 0
            || read_points(eq + 1, k == 0 ? &given->wheel : k == 1 ? &given->roller
                                    : k == 2 ? &given->wheel_right : &given->roller_right) < 0)
            return -1;
    }
    return 0;
}

static void free_points(rr_rig_profiles *pr, rr_nh_table nh[2])
{
    free((void *)nh[0].rows), free((void *)nh[1].rows);
    free((void *)pr->wheel.y), free((void *)pr->wheel.z);
    free((void *)pr->roller.y), free((void *)pr->roller.z);
    free((void *)pr->wheel_right.y), free((void *)pr->wheel_right.z);
    free((void *)pr->roller_right.y), free((void *)pr->roller_right.z);
}

int main(int argc, char **argv)
{
    static rr_rig rig;
    rr_rig_config c;
    rr_rig_geometry g;
    rr_rig_profiles given, pr;
    rr_nh_table nh[2];
    rr_contact_table t;
    rr_rig_params p;
    double rec[RR_REC_COUNT], *data = NULL, *work = NULL, *rig_work = NULL, roller_ref, xi_ref;
    size_t nwork = 0;
    long k, n, len, wlen;
    int st;

    memset(&given, 0, sizeof given);
    memset(nh, 0, sizeof nh);
    rr_rig_config_default(&c);
    if (parse_args(argc, argv, &c, &given, nh) < 0) {
        free_points(&given, nh);
        return 2;
    }
    rr_rig_geometry_from(&c, &g);
    /* the scales and gauge of the configuration; the points of the files */
    rr_rig_profiles_from(&c, &pr);
    if (pr.wheel.n < 0)
        pr.wheel = given.wheel;
    if (pr.roller.n < 0)
        pr.roller = given.roller;
    if (pr.wheel_right.n < 0)
        pr.wheel_right = given.wheel_right;
    if (pr.roller_right.n < 0)
        pr.roller_right = given.roller_right;
    len = rr_rig_table_data_len(&g);
    wlen = rr_rig_profiles_work_len(&pr);
    data = malloc((size_t)(len > 0 ? len : 1) * sizeof *data);
    work = malloc((size_t)(wlen > 0 ? wlen : 1) * sizeof *work);
    /* no profile given: rr_rig_table_build_profiles is rr_rig_table_build */
    if (!data || !work)
        st = RR_ERR_WORKSPACE;
    else if ((st = rr_rig_table_build_profiles(&g, &pr, data, len, work, wlen, &t, NULL)) >= 0
             && (st = rr_rig_params_from(&c, &t, &p)) >= 0
             && (!nh[0].rows || (st = rr_rig_params_set_nonhertz(&p, &nh[0], &nh[1])) >= 0)) {
        /* the creep method's workspace is the caller's, allocated before the
         * run (none for the methods the rig steps with today) */
        nwork = rr_rig_workspace_len(&p);
        if (nwork > 0 && !(rig_work = malloc(nwork * sizeof *rig_work)))
            st = RR_ERR_WORKSPACE;
    }
    if (st < 0 || (st = rr_rig_init(&p, c.roller_speed / c.roller_radius, rig_work, nwork,
                                    &rig)) < 0) {
        fprintf(stderr, "rig_paper: %s\n", rr_status_message(st));
        n = -1;
    } else {
        n = rr_rig_samples(&c);
    }
    for (k = 0; k < n; k++) {
        rr_rig_schedule(&c, k, &roller_ref, &xi_ref);
        st = rr_rig_step(&rig, roller_ref, xi_ref, rec);
        if (st < 0) {
            fprintf(stderr, "rig_paper: sample %ld: %s\n", k, rr_status_message(st));
            break;
        }
        if (fwrite(rec, sizeof rec[0], RR_REC_COUNT, stdout) != RR_REC_COUNT) {
            fprintf(stderr, "rig_paper: cannot write the records\n");
            st = RR_ERR_WORKSPACE;
            break;
        }
    }
    free(rig_work);
    free(work);
    free(data);
    free_points(&given, nh);
    return n < 0 || st < 0 ? 1 : 0;
}
