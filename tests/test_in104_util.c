/*
 * test_in104_util.c - util.h, the course's libutil (library raytrace-util):
 * splitLine on the lines of .scn files and on every rule its header states
 * (separators, runs, the NULL end mark, more words than slots, what it
 * writes into the buffer), and fastInvSqrt against the classic function's
 * known values and its error bound.
 */
#include <math.h>
#include <string.h>

#include "testutil.h"
#include "util.h"

/* The words of out[0..size-1] up to the first NULL, joined with '|'. */
static const char *joined(char **out, int size)
{
    static char text[256];
    text[0] = '\0';
    for (int i = 0; i < size && out[i]; i++) {
        if (i > 0)
            strcat(text, "|");
        strcat(text, out[i]);
    }
    return text;
}

START_TEST(split_line_cuts_a_screen_line_of_a_scene_into_its_numbers)
{
    char line[] = "3,-3,-1, 3,-9,0, 400,400\n";
    char *out[9];
    splitLine(line, out, 9);
    ck_assert_str_eq(joined(out, 9), "3|-3|-1|3|-9|0|400|400");
    ck_assert_ptr_null(out[8]);
}
END_TEST

START_TEST(split_line_counts_a_run_of_separators_as_one)
{
    char line[] = "1,,2 ,\t 3 \r\n";
    char *out[4];
    splitLine(line, out, 4);
    ck_assert_str_eq(joined(out, 4), "1|2|3");
    ck_assert_ptr_null(out[3]);
}
END_TEST

START_TEST(split_line_ignores_separators_before_the_first_and_after_the_last_word)
{
    char line[] = " ,\t5.4, -4.2 ,\n";
    char *out[3];
    splitLine(line, out, 3);
    ck_assert_str_eq(out[0], "5.4");
    ck_assert_str_eq(out[1], "-4.2");
    ck_assert_ptr_null(out[2]);
}
END_TEST

START_TEST(split_line_of_an_empty_or_blank_line_gives_no_word)
{
    char empty[] = "", blank[] = " ,\t\n";
    char *out[2] = {empty, empty};
    splitLine(empty, out, 2);
    ck_assert_ptr_null(out[0]);
    ck_assert_ptr_null(out[1]);
    splitLine(blank, out, 2);
    ck_assert_ptr_null(out[0]);
}
END_TEST

START_TEST(split_line_keeps_every_other_byte_in_words)
{
    char line[] = "#comment 1e-3;x";
    char *out[3];
    splitLine(line, out, 3);
    ck_assert_str_eq(joined(out, 3), "#comment|1e-3;x");
}
END_TEST

START_TEST(split_line_stores_size_words_and_leaves_the_rest_of_the_line)
{
    char line[] = "1,2,3,4,5";
    char *out[3];
    splitLine(line, out, 3);
    ck_assert_str_eq(joined(out, 3), "1|2|3");
    /* Only the separators after the stored words became '\0'. */
    ck_assert_int_eq(memcmp(line, "1\0" "2\0" "3\0" "4,5", 10), 0);
}
END_TEST

START_TEST(split_line_with_one_slot_more_than_expected_tells_a_long_line)
{
    char fits[] = "1 2 3", too_long[] = "1 2 3 4";
    char *out[4];
    splitLine(fits, out, 4);
    ck_assert_ptr_null(out[3]);
    splitLine(too_long, out, 4);
    ck_assert_ptr_nonnull(out[3]);
    ck_assert_str_eq(out[3], "4");
}
END_TEST

START_TEST(split_line_words_point_into_the_buffer)
{
    char line[] = "ab, cd";
    char *out[2];
    splitLine(line, out, 2);
    ck_assert_ptr_eq(out[0], line);
    ck_assert_ptr_eq(out[1], line + 4);
    ck_assert_int_eq(line[2], '\0');
}
END_TEST

START_TEST(split_line_with_no_slot_touches_nothing)
{
    char line[] = "1,2";
    char *sentinel = line;
    splitLine(line, &sentinel, 0);
    splitLine(line, &sentinel, -3);
    ck_assert_str_eq(line, "1,2");
    ck_assert_ptr_eq(sentinel, line);
}
END_TEST

START_TEST(fast_inv_sqrt_gives_the_classic_functions_values)
{
    /* The 0x5f3759df guess and one Newton step, as published: exact bits. */
    ck_assert_float_eq(fastInvSqrt(1.0f), 0x1.ff221ep-1f);
    ck_assert_float_eq(fastInvSqrt(4.0f), 0x1.ff221ep-2f);
    ck_assert_float_eq(fastInvSqrt(0.25f), 0x1.ff221ep+0f);
    ck_assert_float_eq(fastInvSqrt(2.0f), 0x1.69f2bcp-1f);
    ck_assert_float_eq(fastInvSqrt(100.0f), 0x1.98f6f2p-4f);
}
END_TEST

START_TEST(fast_inv_sqrt_is_within_0_18_percent_on_positive_normal_floats)
{
    /* 2^-120 .. 2^120 in steps of 1/64 of an octave. */
    double worst = 0;
    for (int step = -120 * 64; step <= 120 * 64; step++) {
        float x = (float)exp2(step / 64.0);
        double exact = 1 / sqrt((double)x);
        double error = fabs(fastInvSqrt(x) - exact) / exact;
        if (error > worst)
            worst = error;
    }
    ck_assert_double_lt(worst, 1.8e-3);
    ck_assert_double_gt(worst, 1.0e-3); /* it is an approximation */
}
END_TEST

START_TEST(fast_inv_sqrt_of_zero_is_large_and_finite)
{
    float y = fastInvSqrt(0.0f);
    ck_assert(isfinite(y));
    ck_assert_float_eq_tol(y, 1.98177537e19f, 1e13f);
}
END_TEST

static Suite *in104_util_suite(void)
{
    Suite *suite = suite_create("in104_util");

    TCase *split = tcase_create("splitLine");
    tcase_add_test(split, split_line_cuts_a_screen_line_of_a_scene_into_its_numbers);
    tcase_add_test(split, split_line_counts_a_run_of_separators_as_one);
    tcase_add_test(split,
        split_line_ignores_separators_before_the_first_and_after_the_last_word);
    tcase_add_test(split, split_line_of_an_empty_or_blank_line_gives_no_word);
    tcase_add_test(split, split_line_keeps_every_other_byte_in_words);
    tcase_add_test(split, split_line_stores_size_words_and_leaves_the_rest_of_the_line);
    tcase_add_test(split,
        split_line_with_one_slot_more_than_expected_tells_a_long_line);
    tcase_add_test(split, split_line_words_point_into_the_buffer);
    tcase_add_test(split, split_line_with_no_slot_touches_nothing);
    suite_add_tcase(suite, split);

    TCase *fast = tcase_create("fastInvSqrt");
    tcase_add_test(fast, fast_inv_sqrt_gives_the_classic_functions_values);
    tcase_add_test(fast, fast_inv_sqrt_is_within_0_18_percent_on_positive_normal_floats);
    tcase_add_test(fast, fast_inv_sqrt_of_zero_is_large_and_finite);
    suite_add_tcase(suite, fast);
    return suite;
}

RT_CHECK_MAIN(in104_util_suite)
