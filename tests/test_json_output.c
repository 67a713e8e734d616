/*
 * test_json_output.c - every JSON the programs write is valid JSON in valid
 * UTF-8, whatever bytes the names hold, and ends with a newline.
 *
 * `test_json_output` checks the one string writer (apps/common/cli_text.h) in
 * process against worked-out escapes: control characters as \u00XX, each
 * maximal invalid subsequence as one \ufffd (Unicode's table 3-8 of
 * well-formed sequences), valid UTF-8 as it is.  `test_json_output python`
 * has Python's json module read what the writer and the programs write:
 * 400 hostile strings through the writer, each of which must decode to
 * what Python's own UTF-8 decoder gives with errors='replace' (the same
 * maximal-subpart rule, written independently), and rt-export's
 * --stats=json and --explain-json for a scene and an output whose names
 * hold invalid UTF-8, control bytes, quotes and backslashes: both programs'
 * objects parse, end with a newline, and name the scene the same way.
 * Without python3 that entry exits 77, a skip CTest shows.
 */
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_text.h"
#include "testutil.h"

/* ------------------------------------------------------------------ */
/* The writer, in process                                              */

START_TEST(json_strings_escape_controls_and_replace_invalid_bytes)
{
    static const struct {
        const char *in, *out;
    } cases[] = {
        {"plain.scn", "\"plain.scn\""},
        {"q\"b\\s", "\"q\\\"b\\\\s\""},
        {"\x01\x1f\x7f", "\"\\u0001\\u001f\\u007f\""},
        {"a\nb\tc\r", "\"a\\u000ab\\u0009c\\u000d\""},
        {"\x1b[31mred", "\"\\u001b[31mred\""},
        /* C1 controls are escaped, the no-break space is not */
        {"\xc2\x80\xc2\x9f\xc2\xa0", "\"\\u0080\\u009f\xc2\xa0\""},
        /* valid UTF-8 of 2, 3 and 4 bytes stays as it is */
        {"\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80",
         "\"\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80\""},
        {"\xf4\x8f\xbf\xbf", "\"\xf4\x8f\xbf\xbf\""},   /* U+10FFFF */
        /* the line and paragraph separators */
        {"\xe2\x80\xa8\xe2\x80\xa9", "\"\\u2028\\u2029\""},
        /* invalid: one U+FFFD per maximal subpart */
        {"\xff", "\"\\ufffd\""},
        {"a\x80z", "\"a\\ufffdz\""},
        {"\xc0\xaf", "\"\\ufffd\\ufffd\""},             /* overlong '/' */
        {"\xe0\x80\x80", "\"\\ufffd\\ufffd\\ufffd\""},  /* overlong NUL */
        {"\xed\xa0\x80", "\"\\ufffd\\ufffd\\ufffd\""},  /* a surrogate */
        {"\xf4\x90\x80\x80", "\"\\ufffd\\ufffd\\ufffd\\ufffd\""},
        {"\xe2\x82", "\"\\ufffd\""},                    /* cut at the end */
        {"\xe2\x82x", "\"\\ufffdx\""},
        {"\xf0\x9f\x98" "A", "\"\\ufffdA\""},
        {"\xf5\xbf", "\"\\ufffd\\ufffd\""},
        {"", "\"\""},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        char out[256];
        size_t n = cli_json_quote(cases[i].in, out, sizeof out);
        ck_assert_msg(strcmp(out, cases[i].out) == 0, "case %zu: %s", i,
                      out);
        ck_assert_uint_eq(n, strlen(cases[i].out));
    }
}
END_TEST

START_TEST(json_quote_cuts_a_small_buffer_and_counts_all)
{
    char out[6];
    size_t n = cli_json_quote("abc\x01z", out, sizeof out);
    ck_assert_uint_eq(n, strlen("\"abc\\u0001z\""));
    ck_assert_str_eq(out, "\"abc\\");
    ck_assert_uint_eq(cli_json_quote("x", NULL, 0), 3);
}
END_TEST

START_TEST(message_names_have_control_bytes_escaped)
{
    char out[64];
    ck_assert_str_eq(cli_printable("a\x1b[2Jb\n\xff", out, sizeof out),
                     "a\\x1b[2Jb\\x0a\xff");
    char small[8];
    ck_assert_str_eq(cli_printable("abcdefghij", small, sizeof small),
                     "abcd...");
}
END_TEST

/* ------------------------------------------------------------------ */
/* Through Python's json module                                        */

/* Lines "HEX JSON": the bytes of a string in hex, then what the writer
 * made of it; check.py decodes both and compares. */
static const char strings_check[] =
    "import json, sys\n"
    "count = 0\n"
    "for line in open(sys.argv[1], 'rb').read().split(b'\\n'):\n"
    "    if not line:\n"
    "        continue\n"
    "    hexed, written = line.split(b' ', 1)\n"
    "    raw = bytes.fromhex(hexed.decode())\n"
    "    text = written.decode('utf-8')  # strict: the JSON is UTF-8\n"
    "    got = json.loads(text)\n"
    "    want = raw.decode('utf-8', errors='replace')\n"
    "    assert got == want, (raw, text, got, want)\n"
    "    assert all(ord(c) >= 0x20 for c in text), text\n"
    "    count += 1\n"
    "assert count == int(sys.argv[2]), count\n";

/* The i-th hostile string (deterministic): bytes drawn mostly from those
 * that start, continue or break UTF-8 sequences, and controls. */
static size_t hostile(unsigned i, unsigned char *out)
{
    static const unsigned char pool[] = {
        0x00, 0x01, 0x09, 0x0a, 0x1b, 0x1f, 0x22, 0x5c, 0x2f, 0x41, 0x7f,
        0x80, 0x9f, 0xa0, 0xbf, 0xc0, 0xc1, 0xc2, 0xc3, 0xdf, 0xe0, 0xe2,
        0xed, 0xee, 0xef, 0xf0, 0xf4, 0xf5, 0xf8, 0xfe, 0xff, 0x8f, 0x90};
    rt_test_rng rng = {2654435761u * (i + 1)};
    size_t n = 1 + i % 12;
    for (size_t k = 0; k < n; k++) {
        unsigned char b = pool[rt_test_rng_below(&rng, (int)sizeof pool)];
        out[k] = b ? b : 'x'; /* a C string holds no NUL */
    }
    out[n] = '\0';
    return n;
}

START_TEST(python_reads_every_string_the_writer_writes)
{
    char *dir = rt_test_temp_dir();
    FILE *f = fopen(rt_test_in_dir(dir, "strings.txt"), "wb");
    ck_assert_ptr_nonnull(f);
    enum { COUNT = 400 };
    for (unsigned i = 0; i < COUNT; i++) {
        unsigned char raw[16];
        size_t n = hostile(i, raw);
        for (size_t k = 0; k < n; k++)
            fprintf(f, "%02x", raw[k]);
        fputc(' ', f);
        cli_json_string(f, (const char *)raw);
        fputc('\n', f);
    }
    ck_assert_int_eq(fclose(f), 0);
    rt_test_write_file(rt_test_in_dir(dir, "check.py"), strings_check);
    char command[8192];
    snprintf(command, sizeof command,
             "cd '%s' && python3 check.py strings.txt %d", dir, COUNT);
    ck_assert_msg(system(command) == 0, "python's json refused a string");
    rt_test_remove_dir(dir);
}
END_TEST

/* argv: the file holding the program's output, the field, the name's
 * bytes in hex; the last line must end with a newline and be an object
 * whose field is the name as UTF-8 with U+FFFD for invalid bytes. */
static const char object_check[] =
    "import json, sys\n"
    "data = open(sys.argv[1], 'rb').read()\n"
    "assert data.endswith(b'\\n'), data[-20:]\n"
    "line = data.rstrip(b'\\n').split(b'\\n')[-1]\n"
    "o = json.loads(line.decode('utf-8'))\n"
    "want = bytes.fromhex(sys.argv[3]).decode('utf-8', errors='replace')\n"
    "assert o[sys.argv[2]] == want, (o[sys.argv[2]], want)\n"
    "print(o[sys.argv[2]].encode('unicode_escape').decode())\n";

/* Checks `field` of the JSON in `path` against `name`; returns the field
 * as Python printed it (malloc'd). */
static char *check_object(const char *dir, const char *path,
                          const char *field, const char *name)
{
    char hex[512] = "";
    for (size_t k = 0; name[k] && k < 200; k++)
        snprintf(hex + 2 * k, 3, "%02x", (unsigned char)name[k]);
    rt_test_write_file(rt_test_in_dir(dir, "object.py"), object_check);
    char command[8192];
    snprintf(command, sizeof command,
             "cd '%s' && python3 object.py '%s' %s %s > printed.txt", dir,
             path, field, hex);
    ck_assert_msg(system(command) == 0, "the JSON of %s failed its check",
                  path);
    char *printed = rt_test_read_file(rt_test_in_dir(dir, "printed.txt"), NULL);
    ck_assert_ptr_nonnull(printed);
    return printed;
}

static const char hostile_scene[] = "bad\xff\xfe-\x01\x1b[31m-\"q\"-\\-"
                                    "\xe2\x80\xa8-\xc3\xa9.scn";
static const char hostile_output[] = "out\x02\xc0\xaf\".ppm";

/* The cubes scene under the hostile name, in dir. */
static void write_hostile_scene(const char *dir)
{
    char *text = rt_test_read_file(rt_test_source_path("scenes/cubes.scn"),
                                   NULL);
    ck_assert_ptr_nonnull(text);
    rt_test_write_file(rt_test_in_dir(dir, hostile_scene), text);
    free(text);
}

START_TEST(stats_and_explain_json_parse_and_agree_on_hostile_names)
{
    char *dir = rt_test_temp_dir();
    write_hostile_scene(dir);
    const char *stats[] = {hostile_scene, "--size=20x15", "--stats=json",
                           "-q", "--format", "p6", "-o", hostile_output,
                           NULL};
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, stats);
    ck_assert_msg(r.code == 0, "%s", r.err);
    rt_test_write_file(rt_test_in_dir(dir, "stats.txt"), r.err);
    rt_test_output_free(&r);
    char *stats_scene = check_object(dir, "stats.txt", "scene",
                                     hostile_scene);
    free(check_object(dir, "stats.txt", "output", hostile_output));

    const char *explain[] = {hostile_scene, "--size=20x15", "--explain",
                             "10,7", "--explain-json", NULL};
    r = rt_test_run(dir, RT_EXPORT_PATH, explain);
    ck_assert_msg(r.code == 0, "%s", r.err);
    rt_test_write_file(rt_test_in_dir(dir, "explain.txt"), r.out);
    rt_test_output_free(&r);
    char *explain_scene = check_object(dir, "explain.txt", "scene",
                                       hostile_scene);
    /* one writer: the two objects name the scene the same way */
    ck_assert_str_eq(stats_scene, explain_scene);
    ck_assert_ptr_nonnull(strstr(stats_scene, "\\x01\\x1b"));
    free(stats_scene);
    free(explain_scene);
    rt_test_remove_dir(dir);
}
END_TEST

START_TEST(text_explanations_show_control_bytes_escaped)
{
    char *dir = rt_test_temp_dir();
    write_hostile_scene(dir);
    const char *explain[] = {hostile_scene, "--size=20x15", "--explain",
                             "10,7", NULL};
    rt_test_output r = rt_test_run(dir, RT_EXPORT_PATH, explain);
    ck_assert_msg(r.code == 0, "%s", r.err);
    ck_assert_ptr_nonnull(strstr(r.out, "-\\x01\\x1b[31m-"));
    ck_assert_ptr_null(strchr(r.out, '\x1b'));
    rt_test_output_free(&r);
    rt_test_remove_dir(dir);
}
END_TEST

static Suite *json_suite(void)
{
    Suite *s = suite_create("json_output");
    TCase *c = tcase_create("writer");
    tcase_add_test(c, json_strings_escape_controls_and_replace_invalid_bytes);
    tcase_add_test(c, json_quote_cuts_a_small_buffer_and_counts_all);
    tcase_add_test(c, message_names_have_control_bytes_escaped);
    tcase_add_test(c, text_explanations_show_control_bytes_escaped);
    suite_add_tcase(s, c);
    return s;
}

static Suite *python_suite(void)
{
    Suite *s = suite_create("json_output_python");
    TCase *c = tcase_create("python");
    tcase_set_timeout(c, 60);
    tcase_add_test(c, python_reads_every_string_the_writer_writes);
    tcase_add_test(c, stats_and_explain_json_parse_and_agree_on_hostile_names);
    suite_add_tcase(s, c);
    return s;
}

/* `test_json_output` runs the writer's suite; `test_json_output python` the
 * checks through Python's json module, or exits 77 without python3. */
int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "python") == 0) {
        if (!rt_test_have_python_json()) {
            fprintf(stderr, "test_json_output: python3 with its json module is "
                            "not installed; the JSON is not checked\n");
            return RT_TEST_SKIPPED;
        }
        return rt_test_run_suite(python_suite());
    }
    return rt_test_run_suite(json_suite());
}
