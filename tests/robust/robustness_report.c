/*
 * robustness_report.c - runs every robustness case (tests/robust/cases.c)
 * for our renderer and the naive references, in double and float, and
 * prints the markdown table of docs/robustness.md:
 *
 *     cmake --build build --target robustness-report
 *     build/tests/robustness-report > docs/robustness-table.md
 *
 * With case ids as arguments, runs only those.  The numbers are counts of
 * failures by each case's criterion, measured on the same inputs.
 */
#include <stdio.h>
#include <string.h>

#include "robust/robust.h"

static void cell(const rb_result *r)
{
    if (!r->applicable) {
        printf(" n/a |");
        return;
    }
    if (r->failures == 0 && r->nans == 0) {
        printf(" **0** |");
        return;
    }
    printf(" %ld", r->failures);
    if (r->total > 0 && r->failures > 0)
        printf(" (%.3g%%)", 100.0 * (double)r->failures / (double)r->total);
    if (r->nans > 0)
        printf(" + %ld NaN", r->nans);
    printf(" |");
}

static int selected(const char *id, int argc, char **argv)
{
    if (argc < 2)
        return 1;
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], id) == 0)
            return 1;
    return 0;
}

int main(int argc, char **argv)
{
    static const rb_method methods[] = {RB_NAIVE_MT, RB_NAIVE_MT_FMA,
                                        RB_NAIVE_PLANE, RB_OURS};
    printf("| case | setup | failure | of | naive MT d | naive MT f | "
           "MT+FMA d | MT+FMA f | naive plane d | naive plane f | "
           "**ours d** | **ours f** | notes (ours) |\n");
    printf("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    int unclean = 0;
    for (int i = 0; i < rb_case_count; i++) {
        const rb_case *c = &rb_cases[i];
        if (!selected(c->id, argc, argv))
            continue;
        rb_result results[4][2];
        long total = 0;
        for (int m = 0; m < 4; m++)
            for (int p = 0; p < 2; p++) {
                rb_case_run(c, methods[m], p ? RT_PRECISION_FLOAT
                                             : RT_PRECISION_DOUBLE,
                            &results[m][p]);
                if (results[m][p].applicable && results[m][p].total > total)
                    total = results[m][p].total;
            }
        printf("| %s | %s | %s | %ld |", c->id, c->setup, c->criterion, total);
        for (int m = 0; m < 4; m++)
            for (int p = 0; p < 2; p++)
                cell(&results[m][p]);
        const rb_result *d = &results[3][0], *f = &results[3][1];
        int both = f->note[0] && strcmp(d->note, f->note) != 0;
        printf(" %s%s%s%s |\n", d->note, d->note[0] && both ? "; " : "",
               both ? "float: " : "", both ? f->note : "");
        for (int p = 0; p < 2; p++)
            unclean += results[3][p].applicable &&
                       (results[3][p].failures || results[3][p].nans);
        fflush(stdout);
    }
    fprintf(stderr, "robustness-report: %d unclean cells of ours\n", unclean);
    return 0;
}
