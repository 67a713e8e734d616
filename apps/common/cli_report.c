/*
 * cli_report.c - the progress line and the statistics of a render (see
 * cli_report.h).  The JSON is written by hand: a flat object of numbers
 * and a few strings, so a library would buy nothing; strings go through
 * cli_json_string (cli_text.h), valid UTF-8 and valid JSON whatever the
 * names hold.
 */
#include "cli_report.h"

#include <stdint.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/resource.h>

#include "cli_text.h"

void cli_progress_start(cli_progress *progress, FILE *out, int terminal,
                        const char *name, int rows, int width, int samples)
{
    *progress = (cli_progress){.out = out, .name = name,
                               .terminal = terminal, .rows = rows,
                               .rays_per_row = (double)width * samples};
    progress->start = progress->last = cli_clock_seconds();
}

/* "12.3 s", "4 min 05 s", "1 h 02 min" */
static void format_duration(double seconds, char *out, size_t size)
{
    if (seconds < 60.0)
        snprintf(out, size, "%.1f s", seconds);
    else if (seconds < 3600.0)
        snprintf(out, size, "%d min %02d s", (int)(seconds / 60.0),
                 (int)seconds % 60);
    else
        snprintf(out, size, "%d h %02d min", (int)(seconds / 3600.0),
                 (int)(seconds / 60.0) % 60);
}

/* "812k", "3.41M": three significant digits and an SI prefix. */
static void format_rate(double rate, char *out, size_t size)
{
    static const char *prefixes[] = {"", "k", "M", "G", "T"};
    int p = 0;
    while (rate >= 1000.0 && p < 4) {
        rate /= 1000.0;
        p++;
    }
    snprintf(out, size, "%.3g%s", rate, prefixes[p]);
}

/* The columns of the terminal `out` is, re-read at every redraw (so a
 * resized window is followed without a SIGWINCH handler);
 * CLI_PROGRESS_COLUMNS when it does not say. */
static int terminal_columns(FILE *out)
{
    struct winsize size;
    if (ioctl(fileno(out), TIOCGWINSZ, &size) != 0 || size.ws_col == 0)
        return CLI_PROGRESS_COLUMNS;
    return size.ws_col;
}

/* The length of fields[0..count) joined by ", ". */
static size_t joined_length(const char *const *fields, int count)
{
    size_t length = 0;
    for (int i = 0; i < count; i++)
        length += strlen(fields[i]) + (i > 0 ? 2 : 0);
    return length;
}

/* The first byte at or after `text` that starts a UTF-8 character (a cut
 * never leaves half a character). */
static const char *character_start(const char *text)
{
    while (((unsigned char)*text & 0xC0) == 0x80)
        text++;
    return text;
}

size_t cli_progress_fit(int columns, const char *name,
                        const char *const *fields, int count, char *out,
                        size_t size)
{
    static const char head[] = "rendering ", colon[] = ": ",
                      ellipsis[] = "...";
    const size_t decoration = strlen(head) + strlen(colon),
                 dots = strlen(ellipsis);
    if (size == 0)
        return 0;
    size_t limit = (size_t)(columns > 0 ? columns : CLI_PROGRESS_COLUMNS) - 1;
    size_t name_length = strlen(name);
    const char *base = strrchr(name, '/');
    size_t base_length = strlen(base ? base + 1 : name);
    /* the least a name is cut to before a field goes: "..." and its file
     * name */
    size_t least = name_length < dots + base_length ? name_length
                                                      : dots + base_length;
    int kept = count;
    while (kept > 1 && decoration + joined_length(fields, kept) + least > limit)
        kept--;
    size_t fixed = decoration + joined_length(fields, kept);
    size_t budget = limit > fixed ? limit - fixed : 0;

    char line[CLI_PROGRESS_LINE];
    size_t length = (size_t)snprintf(line, sizeof line, "%s", head);
    if (name_length <= budget)
        length += (size_t)snprintf(line + length, sizeof line - length, "%s",
                                   name);
    else {
        size_t tail = budget > dots ? budget - dots : 0;
        length += (size_t)snprintf(
            line + length, sizeof line - length, "%s%s", ellipsis,
            character_start(name + name_length - tail));
    }
    for (int i = 0; i < kept && length < sizeof line; i++)
        length += (size_t)snprintf(line + length, sizeof line - length,
                                   "%s%s", i ? ", " : colon, fields[i]);
    if (length >= sizeof line)
        length = sizeof line - 1;
    /* narrower than the least line: cut at the right edge, on a character */
    if (length > limit)
        length = limit;
    if (length > size - 1)
        length = size - 1;
    while (length > 0 && ((unsigned char)line[length] & 0xC0) == 0x80)
        length--;
    memcpy(out, line, length);
    out[length] = '\0';
    return length;
}

/* Draws the line: in place on a terminal, fitted to its width; elsewhere
 * a whole line.  `last`: the render is over (the final line, without the
 * time left). */
static void draw(cli_progress *p, double elapsed, int last)
{
    char percent[16], spent[32], left[48], rate[48];
    snprintf(percent, sizeof percent, "%3d%%",
             (int)(100.0 * p->done / p->rows));
    format_duration(elapsed, spent, sizeof spent);
    format_duration(elapsed * (p->rows - p->done) / p->done, left,
                    sizeof left);
    strcat(left, " left");
    format_rate(p->rays_per_row * p->done / (elapsed > 0 ? elapsed : 1e-9),
                rate, sizeof rate);
    strcat(rate, " camera rays/s");
    /* in the order shown; the last ones go first when the line is too
     * wide */
    const char *fields[4] = {percent, spent, left, rate};
    if (last)
        fields[2] = rate;
    int count = last ? 3 : 4;
    char name[1024], line[CLI_PROGRESS_LINE];
    cli_printable(p->name, name, sizeof name);
    if (p->terminal) {
        cli_progress_fit(terminal_columns(p->out), name, fields, count, line,
                         sizeof line);
        /* erase to the end of the line: what a longer line left there */
        fprintf(p->out, "\r%s\033[K%s", line, last ? "\n" : "");
    } else {
        cli_progress_fit(CLI_PROGRESS_LINE, name, fields, count, line,
                         sizeof line);
        fprintf(p->out, "%s\n", line);
    }
    fflush(p->out);
    p->shown = 1;
}

int cli_progress_row(void *user, int row)
{
    (void)row;
    cli_progress *p = user;
    p->done++;
    if (!p->terminal)
        return 1;               /* only the final line */
    double elapsed = cli_seconds_since(p->start);
    if (elapsed < 0.5 ||
        (cli_seconds_since(p->last) < 0.1 && p->done < p->rows))
        return 1;
    p->last = cli_clock_seconds();
    draw(p, elapsed, 0);
    return 1;
}

void cli_progress_end(cli_progress *progress)
{
    /* on a terminal, only when a line is there to finish (a short render
     * shows nothing); elsewhere the one line, once a row was counted */
    if (progress->done > 0 && (progress->shown || !progress->terminal))
        draw(progress, cli_seconds_since(progress->start), 1);
}

/* ------------------------------------------------------------------ */

static const char *precision_name(rt_precision p)
{
    return p == RT_PRECISION_FLOAT ? "float" : "double";
}

static const char *kernel_name(rt_kernel_choice k)
{
    return k == RT_KERNEL_SCALAR ? "scalar" : "auto";
}

uint64_t cli_peak_bytes(void)
{
    struct rusage usage;
    if (getrusage(RUSAGE_SELF, &usage) != 0 || usage.ru_maxrss <= 0)
        return 0;
    return (uint64_t)usage.ru_maxrss * 1024;    /* Linux: kilobytes */
}

static const char *accel_name(rt_accel a)
{
    return a == RT_ACCEL_NONE     ? "none"
           : a == RT_ACCEL_OCTREE ? "octree"
           : a == RT_ACCEL_KDTREE ? "kdtree"
                                  : "auto";
}

/* The counters of RT_STATS_MAP's `group`, in its order, as
 * "<value> <title>" joined by ", " (the integer counters of the groups
 * the text lists). */
static void print_text_group(FILE *out, const rt_render_stats *s,
                             const char *group)
{
    const char *between = "";
#define TEXT_(type, name, origin, merge, grp, key, title)                    \
    if (strcmp(#grp, group) == 0) {                                          \
        fprintf(out, "%s%llu %s", between, (unsigned long long)s->name,     \
                title);                                                      \
        between = ", ";                                                      \
    }
    RT_STATS_MAP(TEXT_)
#undef TEXT_
}

/* count / the structure's live facets, 0 without any. */
static double per_facet(const rt_render_stats *s, uint64_t count)
{
    return s->accel_facets > 0 ? (double)count / (double)s->accel_facets
                               : 0.0;
}

void cli_print_stats_text(FILE *out, const rt_render_stats *s,
                          const cli_render_report *r)
{
    const rt_render_options *o = &r->settings->render;
    double tests_per_second = s->seconds > 0 ? s->ray_facet_tests / s->seconds
                                             : 0.0;
    fputs("rays: ", out);
    print_text_group(out, s, "rays");
    fprintf(out, " (%llu in all)\nskipped by the scene analysis: ",
            (unsigned long long)rt_render_stats_rays(s));
    print_text_group(out, s, "rays_skipped");
    fprintf(out,
            "\n"
            "ray-facet tests: %llu (%.3g per second); %llu more without the "
            "analysis and early exits\n"
            "time: load %.3f s, render %.3f s (%s threads, %s kernel, %s), "
            "write %.3f s\n",
            (unsigned long long)s->ray_facet_tests, tests_per_second,
            (unsigned long long)s->ray_facet_tests_skipped, r->load_seconds,
            s->seconds, o->threads == 0 ? "all" : "the given",
            o->kernel == RT_KERNEL_SCALAR ? "scalar" : "fast",
            precision_name(o->precision), r->write_seconds);
    if (r->peak_bytes > 0)
        fprintf(out,
                "memory: peak %.1f MB (%.1f bytes per facet of %d), %.1f MB "
                "by the end of the load\n",
                r->peak_bytes / 1e6,
                r->facet_count > 0 ? (double)r->peak_bytes / r->facet_count
                                   : 0.0,
                r->facet_count, r->load_peak_bytes / 1e6);
    if (!s->accel_used)
        return;
    uint64_t queries = s->accel_queries ? s->accel_queries : 1;
    const char *name = s->accel_kdtree ? "kd-tree" : "octree";
    fprintf(out,
            "%s: built in %.3f s (%.3g facets per second); %llu leaves, "
            "depth %d, %.2f references "
            "per facet (+%llu facets in every ray's list), %.1f MB "
            "(%.1f bytes per facet)\n"
            "%s per query: %.2f traversal steps, %.2f leaves visited, "
            "%.2f facets tested "
            "(brute force: %llu); %llu queries left to brute force\n",
            name, s->accel_build_seconds,
            s->accel_build_seconds > 0
                ? (double)s->accel_facets / s->accel_build_seconds
                : 0.0,
            (unsigned long long)s->accel_leaves,
            s->accel_depth, per_facet(s, s->accel_references),
            (unsigned long long)s->accel_always, s->accel_bytes / 1e6,
            per_facet(s, s->accel_bytes), name,
            (double)s->accel_steps / queries,
            (double)s->accel_leaves_visited / queries,
            (double)s->accel_facet_tests / queries,
            (unsigned long long)s->accel_facets,
            (unsigned long long)s->accel_fallbacks);
}

static void json_number(FILE *out, const char *name, uint64_t value)
{
    fprintf(out, "\"%s\":%llu", name, (unsigned long long)value);
}

static void json_int(FILE *out, const char *name, int value)
{
    fprintf(out, "\"%s\":%d", name, value);
}

static void json_seconds(FILE *out, const char *name, double value)
{
    fprintf(out, "\"%s\":%.6f", name, value);
}

/* The members "key":value of RT_STATS_MAP's `group`, in its order, each
 * but the first after a comma. */
static void print_json_group(FILE *out, const rt_render_stats *s,
                             const char *group)
{
    const char *between = "";
#define JSON_(type, name, origin, merge, grp, key, title)                    \
    if (strcmp(#grp, group) == 0) {                                          \
        fputs(between, out);                                                 \
        _Generic(s->name, double: json_seconds, int: json_int,               \
                 default: json_number)(out, #key, s->name);                  \
        between = ",";                                                       \
    }
    RT_STATS_MAP(JSON_)
#undef JSON_
}

static void print_json_octree(FILE *out, const rt_render_stats *s)
{
    /* "octree" then "kdtree": the structure used has its figures, the
     * other one is null */
    int kd = s->accel_used && s->accel_kdtree;
    int oct = s->accel_used && !s->accel_kdtree;
    for (int which = 0; which < 2; which++) {
        int used = which ? kd : oct;
        fputs(which ? ",\"kdtree\":" : "\"octree\":", out);
        if (!used) {
            fputs("null", out);
            continue;
        }
        fputc('{', out);
        print_json_group(out, s, "octree");
        /* the ratios the text prints, computed once for every reader */
        uint64_t queries = s->accel_queries ? s->accel_queries : 1;
        fprintf(out,
                ",\"references_per_facet\":%.6g,\"bytes_per_facet\":%.6g,"
                "\"steps_per_query\":%.6g",
                per_facet(s, s->accel_references),
                per_facet(s, s->accel_bytes),
                (double)s->accel_steps / (double)queries);
        fputc('}', out);
    }
}

static void print_json_settings(FILE *out, const cli_render_report *r)
{
    const rt_render_options *o = &r->settings->render;
    const rt_region *g = &o->region;
    fprintf(out, "\"full_width\":%d,\"full_height\":%d,", r->full_width,
            r->full_height);
    if (g->x0 || g->y0 || g->x1 || g->y1)
        fprintf(out, "\"region\":[%d,%d,%d,%d],", g->x0, g->y0, g->x1, g->y1);
    else
        fputs("\"region\":null,", out);
    fprintf(out, "\"threads\":%d,\"precision\":\"%s\",\"fast_sqrt\":%s,"
                 "\"depth\":%d,\"samples\":%d,\"sampling\":\"%s\","
                 "\"kernel\":\"%s\",\"accel\":\"%s\",",
            o->threads, precision_name(o->precision),
            o->fast_inv_sqrt ? "true" : "false", o->max_depth, o->samples,
            o->sampling == RT_SAMPLING_STRATIFIED ? "stratified" : "regular",
            kernel_name(o->kernel), accel_name(o->accel));
}

void cli_print_stats_json(FILE *out, const rt_render_stats *s,
                          const cli_render_report *r)
{
    fputs("{\"program\":", out);
    cli_json_string(out, r->program);
    fputs(",\"version\":", out);
    cli_json_string(out, rt_version_string());
    fputs(",\"scene\":", out);
    cli_json_string(out, r->scene);
    fputs(",\"output\":", out);
    cli_json_string(out, r->output);
    fprintf(out, ",\"format\":\"%s\",\"width\":%d,\"height\":%d,",
            rt_image_format_name(r->format), r->width, r->height);
    print_json_group(out, s, "image");
    fputc(',', out);
    print_json_settings(out, r);
    fprintf(out, "\"seconds\":{\"load\":%.6f,", r->load_seconds);
    print_json_group(out, s, "seconds");
    fprintf(out, ",\"write\":%.6f},\"rays\":{", r->write_seconds);
    print_json_group(out, s, "rays");
    fprintf(out, ",\"total\":%llu},\"rays_skipped\":{",
            (unsigned long long)rt_render_stats_rays(s));
    print_json_group(out, s, "rays_skipped");
    fputs("},", out);
    print_json_group(out, s, "tests");
    fputc(',', out);
    print_json_octree(out, s);
    if (r->peak_bytes > 0)
        fprintf(out,
                ",\"memory\":{\"peak_bytes\":%llu,\"load_peak_bytes\":%llu,"
                "\"facets\":%d,\"peak_bytes_per_facet\":%.6g}",
                (unsigned long long)r->peak_bytes,
                (unsigned long long)r->load_peak_bytes, r->facet_count,
                r->facet_count > 0 ? (double)r->peak_bytes / r->facet_count
                                   : 0.0);
    fputs("}\n", out);
}
