/*
 * raytracer.h - reading a scene file, the IN 104 course handout's way
 * (compatibility layer of libraytrace, library raytrace-in104).
 *
 * parse() is the handout's function; freeScene() and renderToPPM() are
 * extensions of this library (the handout has neither).  If a program
 * already defines functions with those two names and other signatures,
 * compile it with -DIN104_NO_EXTENSIONS to hide their declarations.
 *
 *     scene s;
 *     if (0 != parse("cubes.scn", &s))
 *         return 1;                     (the message is already on stderr)
 *     ... s.nbFacets, s.facets[i].n, s.obs ...
 *     renderToPPM(&s, "cubes.ppm");
 *     freeScene(&s);
 *
 * The functions read and write only their arguments (and stderr), so they
 * may run in several threads at once on different scenes.
 */
#ifndef IN104_RAYTRACER_H
#define IN104_RAYTRACER_H

#include "geometry.h"
#include "in104_export.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Reads the .scn file `fname` (the format of docs/scene-format.md, the same
 * files and the same checks as libraytrace's rt_scene_load) into *s.
 *
 * Returns 0 on success; *s is then entirely filled: width, height, obs,
 * screenA, screenB (projected onto the screen plane when the file's B was
 * not perpendicular to AO), nbPoints and points, nbFacets and facets (each
 * with its vertices' coordinates, k, cp and the unit normal n of
 * createFacet(), zero for a zero-area facet), back and s.  points and
 * facets are allocated (NULL when the count is 0): release them with
 * freeScene(s).  Zero-area facets are kept and reported as warnings on
 * stderr ("file:line:column: warning: ...").
 *
 * A file that uses the library's extensions beyond the handout (several
 * lights, transparent facets, a lens aperture) is refused with
 * RT_ERR_FORMAT and a message saying so: this struct has one light, no
 * transparency and a pinhole camera.
 *
 * On failure returns non-zero (the library's rt_status code), prints one
 * line "file:line:column: what was expected, what was found" on stderr,
 * allocates nothing and leaves *s zeroed (so freeScene(s) is harmless).
 * fname is not modified (it is `char *` only for the handout's signature).
 *
 * *s is taken as uninitialised: parse() never frees what it holds.  Parsing
 * into a scene that an earlier parse() filled therefore leaks that scene's
 * points and facets (valgrind reports them "definitely lost"): call
 * freeScene(s) first, as when reloading a file:
 *
 *     freeScene(&s);
 *     if (0 != parse(name, &s)) ...
 */
IN104_API int parse(char *fname, scene *s);

#ifndef IN104_NO_EXTENSIONS

/*
 * Extension: frees the points and facets of a scene filled by parse() and
 * sets them to NULL and their counts to 0; calling it again, or on a zeroed
 * scene, does nothing.  freeScene(NULL) does nothing.
 */
IN104_API void freeScene(scene *s);

/*
 * Extension: renders *s with libraytrace (docs/rendering-model.md: Whitted ray
 * tracing, at most 5 reflections, all cores) and writes the image to
 * ppmFile as an ASCII PPM (P3), replacing the file atomically.
 *
 * The facets are taken from s->facets (a, b, c, k, cp; points and the
 * stored normals are not read), so a scene built or modified by the program
 * renders too.  The rules of docs/scene-format.md apply: width and height
 * in 1..16384, k in [0, 1], finite coordinates, a camera that is not
 * degenerate.
 * Returns 0 on success; otherwise non-zero (an rt_status code) with one
 * line on stderr naming what was wrong, and the file is left untouched.
 */
IN104_API int renderToPPM(const scene *s, const char *ppmFile);

#endif /* IN104_NO_EXTENSIONS */

#ifdef __cplusplus
}
#endif

#endif /* IN104_RAYTRACER_H */
