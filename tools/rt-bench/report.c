/*
 * report.c - rt-bench's table, CSV and run-to-run comparison (see
 * report.h).
 */
#include "report.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The CSV's columns, in order. */
static const char *const columns[] = {
    "scene", "width", "height", "label", "varies", "precision", "fast_sqrt",
    "samples", "sampling", "depth", "runs", "time_median_s", "time_min_s",
    "time_max_s", "pixels", "total_rmse", "total_psnr_db", "total_max",
    "total_differing", "total_over2", "total_differing_pct",
    "total_over2_pct", "num_rmse", "num_psnr_db", "num_max",
    "num_differing", "num_over2", "num_differing_pct", "num_over2_pct",
    "pareto_front"};
#define COLUMN_COUNT ((int)(sizeof columns / sizeof columns[0]))

static void print_psnr(FILE *f, double psnr, int width)
{
    if (isinf(psnr))
        fprintf(f, "%*s", width, "inf");
    else
        fprintf(f, "%*.1f", width, psnr);
}

void bench_print_table(FILE *f, const bench_row *rows, int count)
{
    fprintf(f, "%-19s %-11s %27s | %-35s | %s\n", "", "",
            "time (ms)           ",
            "total error (vs reference)", "numerical (vs double)");
    fprintf(f, "%-19s %-11s %8s %18s | %7s %5s %4s %7s %7s | %7s %4s %7s "
               "%7s  front\n",
            "configuration", "varies", "median", "min - max", "RMSE",
            "PSNR", "max", "%diff", "%>2", "RMSE", "max", "%diff", "%>2");
    for (int i = 0; i < count; i++) {
        const bench_row *r = &rows[i];
        fprintf(f, "%-19s %-11s %8.2f %8.2f - %7.2f | %7.3f ", r->label,
                r->varies, 1e3 * r->median, 1e3 * r->minimum,
                1e3 * r->maximum, r->total.rmse);
        print_psnr(f, r->total.psnr, 5);
        fprintf(f, " %4d %7.3f %7.3f | %7.4f %4d %7.3f %7.3f  %s\n",
                r->total.max_error,
                bench_percent(r->total.differing, r->total.pixels),
                bench_percent(r->total.differing_much, r->total.pixels),
                r->numerical.rmse, r->numerical.max_error,
                bench_percent(r->numerical.differing, r->numerical.pixels),
                bench_percent(r->numerical.differing_much,
                              r->numerical.pixels),
                r->on_front ? "*" : "");
    }
}

static void write_error(FILE *f, const bench_error *e)
{
    fprintf(f, ",%.6g,%.6g,%d,%ld,%ld,%.6g,%.6g", e->rmse,
            isinf(e->psnr) ? INFINITY : e->psnr, e->max_error, e->differing,
            e->differing_much, bench_percent(e->differing, e->pixels),
            bench_percent(e->differing_much, e->pixels));
}

int bench_write_csv(FILE *f, const char *scene, int width, int height,
                    const bench_row *rows, int count)
{
    for (int c = 0; c < COLUMN_COUNT; c++)
        fprintf(f, "%s%s", c ? "," : "", columns[c]);
    fputc('\n', f);
    for (int i = 0; i < count; i++) {
        const bench_row *r = &rows[i];
        fprintf(f, "%s,%d,%d,%s,%s,%s,%d,%d,%s,%d,%d,%.6g,%.6g,%.6g,%ld",
                scene, width, height, r->label, r->varies,
                r->precision == RT_PRECISION_FLOAT ? "float" : "double",
                r->fast_sqrt, r->samples,
                r->sampling == RT_SAMPLING_STRATIFIED ? "stratified"
                                                      : "regular",
                r->depth, r->runs, r->median, r->minimum, r->maximum,
                r->total.pixels);
        write_error(f, &r->total);
        write_error(f, &r->numerical);
        fprintf(f, ",%d\n", r->on_front);
    }
    return !ferror(f);
}

/* Splits `line` at commas in place; returns the number of fields. */
static int split(char *line, char **fields, int max)
{
    int n = 0;
    line[strcspn(line, "\r\n")] = '\0';
    for (char *p = line; n < max;) {
        fields[n++] = p;
        p = strchr(p, ',');
        if (p == NULL)
            break;
        *p++ = '\0';
    }
    return n;
}

static void copy_text(char *to, size_t size, const char *from)
{
    snprintf(to, size, "%s", from);
}

static void read_error(char **field, bench_error *e, long pixels)
{
    e->pixels = pixels;
    e->rmse = strtod(field[0], NULL);
    e->psnr = strtod(field[1], NULL);
    e->max_error = atoi(field[2]);
    e->differing = atol(field[3]);
    e->differing_much = atol(field[4]);
}

int bench_read_csv(const char *path, bench_row **rows, char *message,
                   size_t message_size)
{
    *rows = NULL;
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        snprintf(message, message_size, "%s: cannot open", path);
        return -1;
    }
    char line[2048];
    char *field[COLUMN_COUNT + 1];
    int count = 0, capacity = 0, line_number = 1, ok = 1;
    if (fgets(line, sizeof line, f) == NULL ||
        split(line, field, COLUMN_COUNT + 1) != COLUMN_COUNT ||
        strcmp(field[0], columns[0]) != 0) {
        snprintf(message, message_size, "%s:1: not an rt-bench CSV", path);
        fclose(f);
        return -1;
    }
    while (ok && fgets(line, sizeof line, f) != NULL) {
        line_number++;
        if (split(line, field, COLUMN_COUNT + 1) != COLUMN_COUNT) {
            snprintf(message, message_size, "%s:%d: expected %d fields",
                     path, line_number, COLUMN_COUNT);
            ok = 0;
            break;
        }
        if (count == capacity) {
            capacity = capacity ? 2 * capacity : 64;
            bench_row *grown = realloc(*rows, (size_t)capacity * sizeof **rows);
            if (grown == NULL) {
                snprintf(message, message_size, "out of memory");
                ok = 0;
                break;
            }
            *rows = grown;
        }
        bench_row *r = &(*rows)[count++];
        memset(r, 0, sizeof *r);
        copy_text(r->label, sizeof r->label, field[3]);
        copy_text(r->varies, sizeof r->varies, field[4]);
        r->precision = strcmp(field[5], "float") ? RT_PRECISION_DOUBLE
                                                 : RT_PRECISION_FLOAT;
        r->fast_sqrt = atoi(field[6]);
        r->samples = atoi(field[7]);
        r->sampling = strcmp(field[8], "stratified") ? RT_SAMPLING_REGULAR
                                                     : RT_SAMPLING_STRATIFIED;
        r->depth = atoi(field[9]);
        r->runs = atoi(field[10]);
        r->median = strtod(field[11], NULL);
        r->minimum = strtod(field[12], NULL);
        r->maximum = strtod(field[13], NULL);
        long pixels = atol(field[14]);
        read_error(&field[15], &r->total, pixels);
        read_error(&field[22], &r->numerical, pixels);
        r->on_front = atoi(field[29]);
    }
    fclose(f);
    if (!ok) {
        free(*rows);
        *rows = NULL;
        return -1;
    }
    return count;
}

/* A value as it reads back from the CSV (%.6g). */
static double as_written(double value)
{
    char text[32];
    snprintf(text, sizeof text, "%.6g", value);
    return strtod(text, NULL);
}

static int same_error(const bench_error *now, const bench_error *before)
{
    return as_written(now->rmse) == before->rmse &&
           now->max_error == before->max_error &&
           now->differing == before->differing &&
           now->differing_much == before->differing_much;
}

int bench_compare_runs(FILE *f, const bench_row *now, int now_count,
                       const bench_row *before, int before_count)
{
    int matched = 0, errors_equal = 0, within = 0, missing = 0;
    double worst_change = 0.0;
    const char *worst_label = "";
    for (int i = 0; i < now_count; i++) {
        const bench_row *a = &now[i], *b = NULL;
        for (int j = 0; j < before_count && b == NULL; j++) {
            if (!strcmp(before[j].label, a->label))
                b = &before[j];
        }
        if (b == NULL) {
            fprintf(f, "  %s: not in the earlier run\n", a->label);
            missing++;
            continue;
        }
        matched++;
        int equal = same_error(&a->total, &b->total) &&
                    same_error(&a->numerical, &b->numerical);
        errors_equal += equal;
        if (!equal)
            fprintf(f, "  %s: errors differ (total RMSE %.6g now, %.6g "
                       "before)\n",
                    a->label, a->total.rmse, b->total.rmse);
        int inside = (a->median >= b->minimum && a->median <= b->maximum) ||
                     (b->median >= a->minimum && b->median <= a->maximum);
        within += inside;
        double change = b->median > 0 ? a->median / b->median - 1.0 : 0.0;
        if (fabs(change) > fabs(worst_change)) {
            worst_change = change;
            worst_label = a->label;
        }
        if (!inside)
            fprintf(f, "  %s: median %.2f ms now, %.2f ms before (%+.1f%%), "
                       "outside both spreads [%.2f, %.2f] and [%.2f, %.2f] "
                       "ms\n",
                    a->label, 1e3 * a->median, 1e3 * b->median,
                    100.0 * change, 1e3 * a->minimum, 1e3 * a->maximum,
                    1e3 * b->minimum, 1e3 * b->maximum);
    }
    missing += before_count - matched;
    fprintf(f, "agreement with the earlier run: %d of %d configurations "
               "matched; errors identical in %d; median time within the "
               "other run's min-max spread in %d (largest change %+.1f%%, "
               "%s)\n",
            matched, now_count, errors_equal, within, 100.0 * worst_change,
            worst_label);
    return missing == 0 && errors_equal == matched;
}
