/*
 * cli_text.h - names as the programs show them: in a message on a terminal
 * (control bytes escaped, so that a file name cannot move the cursor or
 * change the colours) and in a JSON string (always valid UTF-8 and valid
 * JSON, whatever bytes the name holds).  Every JSON output of the programs
 * (--stats=json, --explain-json) writes its strings with cli_json_string,
 * so that all of them escape a name the same way.
 *
 * The JSON rule (docs/command-line.md, "Strings in the JSON"):
 *   - `"` and `\` as `\"` and `\\`;
 *   - the control characters U+0000..U+001F, U+007F..U+009F and the line
 *     and paragraph separators U+2028, U+2029 as `\u00XX` (`\u2028`);
 *   - valid UTF-8 as it is (RFC 3629: no overlong form, no surrogate, at
 *     most U+10FFFF);
 *   - each maximal invalid subsequence (Unicode 15, section 3.9, "U+FFFD
 *     substitution of maximal subparts") as one `\ufffd`, the replacement
 *     character, which every JSON reader decodes.
 * Thread-safe (no state).
 */
#ifndef RAYTRACE_CLI_TEXT_H
#define RAYTRACE_CLI_TEXT_H

#include <stddef.h>
#include <stdio.h>

/* `text` with each control byte (0x00..0x1F, 0x7F) written as \xHH, into
 * out[0..size) (NUL-terminated; cut with "..." when it does not fit).
 * Returns out. */
const char *cli_printable(const char *text, char *out, size_t size);

/* Writes `text` as a JSON string, quotes included, on `out`. */
void cli_json_string(FILE *out, const char *text);

/* The same into out[0..size) (NUL-terminated, cut when it does not fit);
 * returns the length of the whole string, as snprintf does. */
size_t cli_json_quote(const char *text, char *out, size_t size);

/* The up axis of a scene's automatic camera and why, into out[0..size):
 * "+z up (from the comment on line 3)"; 1, or 2 when --up-axis chose it;
 * 0 (out empty) when the scene has its own camera. */
struct rt_scene;
int cli_up_axis_text(const struct rt_scene *scene, char *out, size_t size);

/* The load's note about it on stream, "PROGRAM: NAME: note: automatic
 * camera with +z up (...); --up-axis picks another" (without the advice
 * when --up-axis chose it); nothing for a scene with its own camera. */
void cli_print_up_note(FILE *stream, const char *program, const char *name,
                       const struct rt_scene *scene);

#endif /* RAYTRACE_CLI_TEXT_H */
