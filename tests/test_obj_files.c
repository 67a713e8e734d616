/*
 * test_obj_files.c - the files a scene names (src/formats/resolve.c and
 * the OBJ reader's libraries): rt_resolve_in_folder keeps to the scene's
 * folder (absolute names, `..` and links out refused with one message that
 * does not tell a missing file from a present one), never blocks on a
 * FIFO, reads at most its limit; a load reads each file once however it is
 * spelt, within its budget, and lists what it read (rt_scene_source); an
 * OBJ naming itself is not read as a library; nothing of a library is
 * quoted before its first `newmtl`; a `usemtl` before its `mtllib` gets its
 * material; a parse from memory reads no file unless given a resolver.
 * Every input is generated in a temporary folder.
 */
#define _GNU_SOURCE 1

#include <check.h>
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "testutil.h"

static const char triangle[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
static const char red_library[] = "newmtl red\nKd 1 0 0\n";

/* Two sibling folders: the scene's, and one beside it ("outside"). */
typedef struct folders {
    char *scene_dir, *outside_dir;
    const char *outside_base;       /* the outside folder's own name */
} folders;

static folders make_folders(void)
{
    folders f = {rt_test_temp_dir(), rt_test_temp_dir(), NULL};
    f.outside_base = strrchr(f.outside_dir, '/') + 1;
    return f;
}

static void remove_folders(folders *f)
{
    rt_test_remove_dir(f->scene_dir);
    rt_test_remove_dir(f->outside_dir);
}

static void write_text(const char *dir, const char *name, const char *text)
{
    char *path = rt_test_join(dir, name);
    rt_test_write_bytes(path, text, strlen(text));
    free(path);
}

static void make_link(const char *dir, const char *name, const char *target)
{
    char *path = rt_test_join(dir, name);
    ck_assert_msg(symlink(target, path) == 0, "symlink %s: %s", path,
                  strerror(errno));
    free(path);
}

/* Loads dir/name with the default options; fails the test on a refusal. */
static rt_scene *load(const char *dir, const char *name)
{
    char *path = rt_test_join(dir, name);
    rt_scene *scene = NULL;
    rt_error error;
    ck_assert_msg(rt_scene_load(path, NULL, &scene, &error) == RT_OK, "%s: %s",
                  path, error.message);
    free(path);
    return scene;
}

static rt_rgb8 facet_color(const rt_scene *scene, int i)
{
    rt_facet_info f = {.size = sizeof f};
    rt_scene_facet(scene, i, &f);
    return f.color;
}

/* The message rt_resolve_in_folder gives `reference` for a scene in
 * `dir`, with the reference itself replaced by "REF". */
static void refusal_of(const char *dir, const char *reference, char *out,
                       size_t size)
{
    char *scene_name = rt_test_join(dir, "scene.obj");
    rt_resolved_file file = {(char *)1, 7, (char *)1, 1, 1};
    rt_error error;
    memset(&error, 0, sizeof error);
    rt_status status = rt_resolve_in_folder(NULL, scene_name, reference,
                                            1 << 20, &file, &error);
    ck_assert_msg(status != RT_OK, "`%s` was read", reference);
    ck_assert_msg(file.data == (char *)1 && file.length == 7,
                  "a refusal filled the file");
    const char *at = strstr(error.message, reference);
    ck_assert_msg(at != NULL, "`%s` is not named: %s", reference,
                  error.message);
    snprintf(out, size, "%.*sREF%s", (int)(at - error.message),
             error.message, at + strlen(reference));
    free(scene_name);
}

START_TEST(names_leading_out_of_the_folder_get_one_message_whether_or_not_the_file_exists)
{
    folders f = make_folders();
    write_text(f.outside_dir, "present.mtl", "newmtl SECRET-LINE\nKd 1 0 0\n");
    char *fifo = rt_test_join(f.outside_dir, "fifo.mtl");
    ck_assert_int_eq(mkfifo(fifo, 0600), 0);
    free(fifo);
    char up[3][512];
    const char *names[] = {"present.mtl", "missing.mtl", "fifo.mtl"};
    for (int i = 0; i < 3; i++) {
        snprintf(up[i], sizeof up[i], "../%s/%s", f.outside_base, names[i]);
        char link[64];
        snprintf(link, sizeof link, "link-%d.mtl", i);
        make_link(f.scene_dir, link, up[i]);
    }
    make_link(f.scene_dir, "absolute.mtl", "/etc/passwd");
    /* Every way out, to a file that exists, one that does not and a FIFO:
     * one message, the same but for the name. */
    const char *references[] = {up[0], up[1], up[2], "/etc/passwd",
                                "/etc/no-such-file-here", "link-0.mtl",
                                "link-1.mtl", "link-2.mtl", "absolute.mtl",
                                "sub/../../x.mtl"};
    char first[RT_ERROR_MESSAGE_SIZE], other[RT_ERROR_MESSAGE_SIZE];
    refusal_of(f.scene_dir, references[0], first, sizeof first);
    ck_assert_ptr_nonnull(strstr(first, "must lie in the scene's folder"));
    for (size_t i = 1; i < sizeof references / sizeof *references; i++) {
        refusal_of(f.scene_dir, references[i], other, sizeof other);
        ck_assert_str_eq(other, first);
    }
    /* Through the OBJ reader: the same, the mesh grey, nothing quoted. */
    char text[1024];
    snprintf(text, sizeof text, "mtllib %s\nmtllib /etc/passwd\n"
                                "mtllib link-0.mtl\nusemtl SECRET-LINE\n%s",
             up[0], triangle);
    write_text(f.scene_dir, "scene.obj", text);
    rt_scene *scene = load(f.scene_dir, "scene.obj");
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "must lie in the scene's folder"),
                     3);
    ck_assert_int_eq(rt_test_count_warnings(scene, "Kd"), 0);
    ck_assert_int_eq(rt_test_count_warnings(scene, "root"), 0);
    rt_rgb8 c = facet_color(scene, 0);
    ck_assert(c.r == 204 && c.g == 204 && c.b == 204);
    ck_assert_int_eq(rt_scene_source_count(scene), 1);
    rt_scene_destroy(scene);
    remove_folders(&f);
}
END_TEST

START_TEST(links_and_folders_inside_the_folder_are_followed)
{
    folders f = make_folders();
    char *sub = rt_test_join(f.scene_dir, "sub");
    ck_assert_int_eq(mkdir(sub, 0700), 0);
    write_text(sub, "m.mtl", red_library);
    make_link(f.scene_dir, "alias.mtl", "sub/m.mtl");
    make_link(sub, "up.mtl", "../alias.mtl");   /* .. that stays inside */
    char *scene_name = rt_test_join(f.scene_dir, "scene.obj");
    const char *references[] = {"sub/m.mtl", "alias.mtl", "sub/up.mtl",
                                "./sub//m.mtl"};
    struct stat st;
    char *target = rt_test_join(sub, "m.mtl");
    ck_assert_int_eq(stat(target, &st), 0);
    for (size_t i = 0; i < sizeof references / sizeof *references; i++) {
        rt_resolved_file file;
        rt_error error;
        ck_assert_msg(rt_resolve_in_folder(NULL, scene_name, references[i],
                                           1 << 20, &file, &error) == RT_OK,
                      "%s: %s", references[i], error.message);
        ck_assert_uint_eq(file.length, strlen(red_library));
        ck_assert_int_eq(memcmp(file.data, red_library, file.length), 0);
        ck_assert(file.device == (uint64_t)st.st_dev &&
                  file.inode == (uint64_t)st.st_ino);
        ck_assert_ptr_nonnull(strstr(file.name, references[i]));
        free(file.data);
        free(file.name);
    }
    /* A folder is no library. */
    char message[RT_ERROR_MESSAGE_SIZE];
    refusal_of(f.scene_dir, "sub", message, sizeof message);
    ck_assert_ptr_nonnull(strstr(message, "a folder"));
    free(target);
    target = rt_test_join(sub, "up.mtl");
    unlink(target);
    free(target);
    target = rt_test_join(sub, "m.mtl");
    unlink(target);
    free(target);
    free(sub);
    free(scene_name);
    remove_folders(&f);
}
END_TEST

static int resolve_fifo(void *arg, char *message, size_t size)
{
    const char *dir = arg;
    alarm(10);                  /* a blocked open would end here */
    char *scene_name = rt_test_join(dir, "scene.obj");
    rt_resolved_file file;
    rt_error error;
    rt_status status = rt_resolve_in_folder(NULL, scene_name, "fifo.mtl",
                                            1 << 20, &file, &error);
    snprintf(message, size, "%s", error.message);
    free(scene_name);
    return status == RT_ERR_IO ? 0 : 1;
}

START_TEST(a_fifo_named_as_a_library_is_refused_without_blocking)
{
    folders f = make_folders();
    char *fifo = rt_test_join(f.scene_dir, "fifo.mtl");
    ck_assert_int_eq(mkfifo(fifo, 0600), 0);
    free(fifo);
    char message[1024];
    int code = rt_test_in_child(resolve_fifo, f.scene_dir, message,
                                sizeof message);
    ck_assert_msg(code == 0, "exit %d: %s", code, message);
    ck_assert_ptr_nonnull(strstr(message, "a FIFO, not a regular file"));
    remove_folders(&f);
}
END_TEST

START_TEST(a_file_larger_than_the_limit_is_refused_unread)
{
    folders f = make_folders();
    write_text(f.scene_dir, "m.mtl", red_library);
    char *scene_name = rt_test_join(f.scene_dir, "scene.obj");
    rt_resolved_file file = {NULL, 0, NULL, 0, 0};
    rt_error error;
    ck_assert_int_eq(rt_resolve_in_folder(NULL, scene_name, "m.mtl", 5,
                                          &file, &error),
                     RT_ERR_LIMIT);
    ck_assert_ptr_null(file.data);
    ck_assert_ptr_nonnull(strstr(error.message, "more than the 5 bytes"));
    free(scene_name);
    remove_folders(&f);
}
END_TEST

START_TEST(names_in_messages_have_their_control_bytes_escaped)
{
    folders f = make_folders();
    char *scene_name = rt_test_join(f.scene_dir, "scene.obj");
    rt_resolved_file file;
    rt_error error;
    rt_resolve_in_folder(NULL, scene_name, "/\x1b[2J\x07", 10, &file,
                         &error);
    ck_assert_ptr_null(strchr(error.message, '\x1b'));
    ck_assert_ptr_null(strchr(error.message, '\x07'));
    ck_assert_ptr_nonnull(strstr(error.message, "\\x1B[2J\\x07"));
    /* A file read: its name is the path as given (data, as the scene's
     * sources list it); what prints it escapes it, as the warnings below
     * and rt__error_set do. */
    write_text(f.scene_dir, "e\x1b]0;x.mtl", red_library);
    ck_assert_int_eq(rt_resolve_in_folder(NULL, scene_name, "e\x1b]0;x.mtl",
                                          100, &file, &error),
                     RT_OK);
    ck_assert_ptr_nonnull(strstr(file.name, "e\x1b]0;x.mtl"));
    free(file.data);
    free(file.name);
    /* And through the OBJ reader's warnings. */
    write_text(f.scene_dir, "scene.obj",
               "mtllib \x1b[31mgone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
               "f 1 2 3\n");
    rt_scene *scene = load(f.scene_dir, "scene.obj");
    ck_assert_int_eq(rt_test_count_warnings(scene, "\x1b"), 0);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "`\\x1B[31mgone.mtl` is not read"),
                     1);
    rt_scene_destroy(scene);
    free(scene_name);
    remove_folders(&f);
}
END_TEST

/* A resolver over rt_resolve_in_folder that counts what it is asked. */
typedef struct counting {
    int calls;
    size_t bytes, first_limit, last_limit;
} counting;

static rt_status count_calls(void *user, const char *scene_name,
                             const char *reference, size_t limit,
                             rt_resolved_file *file, rt_error *error)
{
    counting *c = user;
    if (c->calls++ == 0)
        c->first_limit = limit;
    c->last_limit = limit;
    rt_status status = rt_resolve_in_folder(NULL, scene_name, reference,
                                            limit, file, error);
    if (status == RT_OK)
        c->bytes += file->length;
    return status;
}

START_TEST(one_library_under_a_thousand_spellings_is_read_once)
{
    folders f = make_folders();
    write_text(f.scene_dir, "m.mtl", red_library);
    make_link(f.scene_dir, "alias.mtl", "m.mtl");
    char *m = rt_test_join(f.scene_dir, "m.mtl"),
          *hard = rt_test_join(f.scene_dir,
                                                         "hard.mtl");
    ck_assert_int_eq(link(m, hard), 0);
    /* 1,000 spellings: ./ repeated, doubled slashes, the link, the hard
     * link. */
    size_t size = 1000 * 128 + 256, used = 0;
    char *text = malloc(size);
    ck_assert_ptr_nonnull(text);
    for (int i = 0; i < 998; i++) {
        used += (size_t)snprintf(text + used, size - used, "mtllib ");
        for (int k = 0; k < i % 30; k++)
            used += (size_t)snprintf(text + used, size - used,
                                     i % 2 ? ".//" : "./");
        used += (size_t)snprintf(text + used, size - used, "m.mtl\n");
    }
    used += (size_t)snprintf(text + used, size - used,
                             "mtllib alias.mtl\nmtllib hard.mtl\n"
                             "usemtl red\n%s", triangle);
    write_text(f.scene_dir, "scene.obj", text);
    char *path = rt_test_join(f.scene_dir, "scene.obj");
    counting c = {0, 0, 0, 0};
    rt_load_options options;
    rt_load_options_init(&options);
    options.resolve = count_calls;
    options.resolve_user = &c;
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(rt_scene_load(path, &options, &scene, &error) == RT_OK, "%s",
                  error.message);
    /* One call for the canonical spelling, one each for the two links
     * (known by their device and inode once read): 3 reads in all. */
    ck_assert_int_eq(c.calls, 3);
    ck_assert_uint_eq(c.bytes, 3 * strlen(red_library));
    ck_assert_int_eq(rt_scene_source_count(scene), 2);
    ck_assert_ptr_nonnull(strstr(rt_scene_source_at(scene, 1)->name,
                                 "m.mtl"));
    ck_assert_int_eq(facet_color(scene, 0).r, 255);
    /* The budget: 64 MiB plus 16 bytes per byte of the scene, less what
     * was read. */
    ck_assert_uint_eq(c.first_limit, ((size_t)64 << 20) + 16 * used);
    ck_assert_uint_eq(c.last_limit,
                      c.first_limit - 2 * strlen(red_library));
    rt_scene_destroy(scene);
    free(text);
    free(path);
    free(m);
    free(hard);
    remove_folders(&f);
}
END_TEST

/* A resolver that gives more than it is allowed. */
static rt_status give_too_much(void *user, const char *scene_name,
                               const char *reference, size_t limit,
                               rt_resolved_file *file, rt_error *error)
{
    (void)user, (void)scene_name, (void)reference, (void)error;
    file->length = limit + 1;
    file->data = malloc(file->length);
    memset(file->data, 'x', file->length);
    file->name = strdup("too-much");
    file->device = file->inode = 0;
    return RT_OK;
}

START_TEST(a_resolver_that_gives_more_than_the_budget_is_refused)
{
    rt_load_options options;
    rt_load_options_init(&options);
    options.resolve = give_too_much;
    options.format = RT_SCENE_FORMAT_OBJ;
    const char *text = "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    rt_scene *scene;
    ck_assert_int_eq(
        rt_scene_parse(text, strlen(text), "m.obj", &options, &scene, NULL),
        RT_OK);
    ck_assert_int_eq(rt_test_count_warnings(scene, "more than the"), 1);
    ck_assert_int_eq(rt_scene_source_count(scene), 0);
    rt_scene_destroy(scene);
}
END_TEST

START_TEST(an_obj_naming_itself_as_its_library_is_read_once_and_not_quoted)
{
    folders f = make_folders();
    /* Read as a library, its own lines would define `a` as red. */
    char text[1024];
    snprintf(text, sizeof text, "# SECRET-LINE\nnewmtl a\nKd 1 0 0\n"
                                "usemtl a\n");
    size_t used = strlen(text);
    for (int i = 0; i < 20; i++)
        used += (size_t)snprintf(text + used, sizeof text - used,
                                 "mtllib %sself.obj\n", i % 2 ? "./" : "");
    snprintf(text + used, sizeof text - used, "%s", triangle);
    write_text(f.scene_dir, "self.obj", text);
    char *path = rt_test_join(f.scene_dir, "self.obj");
    counting c = {0, 0, 0, 0};
    rt_load_options options;
    rt_load_options_init(&options);
    options.resolve = count_calls;
    options.resolve_user = &c;
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(rt_scene_load(path, &options, &scene, &error) == RT_OK, "%s",
                  error.message);
    ck_assert_int_eq(c.calls, 1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "is this OBJ file itself"),
                     1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "SECRET"), 0);
    /* `Kd` once, as a statement the OBJ reader does not understand. */
    ck_assert_int_eq(rt_test_count_warnings(scene, "`Kd`"), 1);
    ck_assert_int_eq(facet_color(scene, 0).r, 204);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "material `a` is defined in no"),
                     1);
    ck_assert_int_eq(rt_scene_source_count(scene), 1);
    struct stat st;
    ck_assert_int_eq(stat(path, &st), 0);
    const rt_scene_source *self = rt_scene_source_at(scene, 0);
    ck_assert_str_eq(self->name, path);
    ck_assert(self->device == (uint64_t)st.st_dev &&
              self->inode == (uint64_t)st.st_ino);
    ck_assert_uint_eq(self->bytes, strlen(text));
    rt_scene_destroy(scene);
    free(path);
    remove_folders(&f);
}
END_TEST

START_TEST(nothing_of_a_library_before_its_first_newmtl_is_quoted)
{
    folders f = make_folders();
    write_text(f.scene_dir, "notes.mtl",
               "root:x:0:0:SECRET-LINE:/root:/bin/sh\nKd 1 0 0\n"
               "\x1b[31m terminal\n");
    write_text(f.scene_dir, "mixed.mtl",
               "SECRET-LINE one\nSECRET-LINE two\nnewmtl red\nKd 1 0 0\n");
    write_text(f.scene_dir, "scene.obj",
               "mtllib notes.mtl\nmtllib mixed.mtl\nusemtl red\n"
               "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    rt_scene *scene = load(f.scene_dir, "scene.obj");
    ck_assert_int_eq(rt_test_count_warnings(scene, "SECRET"), 0);
    ck_assert_int_eq(rt_test_count_warnings(scene, "root"), 0);
    ck_assert_int_eq(rt_test_count_warnings(scene, "\x1b"), 0);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "notes.mtl:1:1: warning: defines "
                                          "no material (it has no `newmtl`): "
                                          "its 3 statements are ignored"),
                     1);
    ck_assert_int_eq(rt_test_count_warnings(scene, "mixed.mtl:1:1: warning: 2 "
                                          "statements before the first "
                                          "`newmtl` are ignored"),
                     1);
    ck_assert_int_eq(facet_color(scene, 0).r, 255);
    ck_assert_int_eq(rt_scene_source_count(scene), 3);
    rt_scene_destroy(scene);
    remove_folders(&f);
}
END_TEST

START_TEST(a_usemtl_before_its_mtllib_gets_its_material)
{
    folders f = make_folders();
    write_text(f.scene_dir, "m.mtl", red_library);
    write_text(f.scene_dir, "scene.obj",
               "usemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
               "usemtl nowhere\nf 1 3 2\nusemtl red\nf 2 1 3\n"
               "mtllib m.mtl\n");
    rt_scene *scene = load(f.scene_dir, "scene.obj");
    ck_assert_int_eq(facet_color(scene, 0).r, 255);
    ck_assert_int_eq(facet_color(scene, 0).g, 0);
    ck_assert_int_eq(facet_color(scene, 1).r, 204);
    ck_assert_int_eq(facet_color(scene, 2).r, 255);
    ck_assert_int_eq(rt_test_count_warnings(scene, "material `red`"), 0);
    ck_assert_int_eq(rt_test_count_warnings(scene,
                                            "scene.obj:6:8: warning: material "
                                          "`nowhere` is defined in no"),
                     1);
    rt_scene_destroy(scene);
    remove_folders(&f);
}
END_TEST

/* A resolver serving one library from memory, whatever is asked. */
static rt_status from_memory(void *user, const char *scene_name,
                             const char *reference, size_t limit,
                             rt_resolved_file *file, rt_error *error)
{
    (void)scene_name, (void)limit, (void)error;
    const char *text = user;
    file->length = strlen(text);
    file->data = malloc(file->length);
    memcpy(file->data, text, file->length);
    file->name = strdup(reference);
    file->device = file->inode = 0;
    return RT_OK;
}

START_TEST(a_parse_from_memory_reads_a_file_only_through_a_resolver)
{
    folders f = make_folders();
    write_text(f.scene_dir, "m.mtl", red_library);
    char *name = rt_test_join(f.scene_dir, "scene.obj");
    const char *text = "mtllib m.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\n"
                       "v 0 1 0\nf 1 2 3\n";
    rt_scene *scene;
    ck_assert_int_eq(
        rt_scene_parse(text, strlen(text), name, NULL, &scene, NULL), RT_OK);
    ck_assert_int_eq(facet_color(scene, 0).r, 204);
    ck_assert_int_eq(rt_test_count_warnings(scene, "without a resolver"), 1);
    ck_assert_int_eq(rt_scene_source_count(scene), 0);
    rt_scene_destroy(scene);
    rt_load_options options;
    rt_load_options_init(&options);
    options.resolve = rt_resolve_in_folder;
    ck_assert_int_eq(
        rt_scene_parse(text, strlen(text), name, &options, &scene, NULL),
        RT_OK);
    ck_assert_int_eq(facet_color(scene, 0).r, 255);
    ck_assert_int_eq(rt_scene_source_count(scene), 1);
    rt_scene_destroy(scene);
    options.resolve = from_memory;
    options.resolve_user = (void *)"newmtl red\nKd 0 1 0\n";
    ck_assert_int_eq(
        rt_scene_parse(text, strlen(text), name, &options, &scene, NULL),
        RT_OK);
    ck_assert_int_eq(facet_color(scene, 0).g, 255);
    ck_assert_str_eq(rt_scene_source_at(scene, 0)->name, "m.mtl");
    rt_scene_destroy(scene);
    free(name);
    remove_folders(&f);
}
END_TEST

static int write_to_fifo(void *arg, char *message, size_t size)
{
    (void)message, (void)size;
    FILE *file = fopen(arg, "w");
    if (file == NULL)
        return 1;
    fputs(rt_test_small_scene, file);
    return fclose(file) != 0;
}

START_TEST(a_scene_file_that_is_a_fifo_still_loads_and_lists_no_identity)
{
    folders f = make_folders();
    char *fifo = rt_test_join(f.scene_dir, "scene.scn");
    ck_assert_int_eq(mkfifo(fifo, 0600), 0);
    rt_test_child writer = rt_test_child_start(write_to_fifo, fifo);
    ck_assert_int_gt(writer.pid, 0);
    rt_scene *scene;
    rt_error error;
    ck_assert_msg(rt_scene_load(fifo, NULL, &scene, &error) == RT_OK, "%s",
                  error.message);
    ck_assert_int_eq(rt_scene_source_count(scene), 1);
    const rt_scene_source *s = rt_scene_source_at(scene, 0);
    ck_assert(s->device == 0 && s->inode == 0);
    ck_assert_uint_eq(s->bytes, strlen(rt_test_small_scene));
    rt_scene_destroy(scene);
    char note[64];
    ck_assert_int_ne(rt_test_child_finish(&writer, note, sizeof note), -1);
    free(fifo);
    remove_folders(&f);
}
END_TEST

START_TEST(a_cancel_flag_raised_before_a_load_cancels_it)
{
    folders f = make_folders();
    write_text(f.scene_dir, "scene.obj", triangle);
    write_text(f.scene_dir, "scene.scn", rt_test_small_scene);
    rt_cancel *cancel;
    ck_assert_int_eq(rt_cancel_create(&cancel, NULL), RT_OK);
    rt_cancel_request(cancel);
    rt_load_options options;
    rt_load_options_init(&options);
    options.cancel = cancel;
    const char *names[] = {"scene.obj", "scene.scn"};
    for (int i = 0; i < 2; i++) {
        char *path = rt_test_join(f.scene_dir, names[i]);
        rt_scene *scene = (rt_scene *)1;
        rt_error error;
        ck_assert_int_eq(rt_scene_load(path, &options, &scene, &error),
                         RT_ERR_CANCELLED);
        ck_assert_ptr_null(scene);
        ck_assert_ptr_nonnull(strstr(error.message, "cancelled"));
        free(path);
    }
    rt_cancel_destroy(cancel);
    remove_folders(&f);
}
END_TEST

/* Every OBJ of the fuzzer's corpus, split and named as fuzz_obj.c does
 * (the library after a line `#mtl` becomes m.mtl beside it): a refusal
 * has a message, a scene has no facet without area and quotes nothing of
 * a library's lines before its first `newmtl`. */
START_TEST(the_obj_corpus_replays_without_fault)
{
    const char *corpus = rt_test_source_path("tests/fuzz/corpus/obj");
    char *corpus_dir = strdup(corpus);
    DIR *dir = opendir(corpus_dir);
    ck_assert_msg(dir != NULL, "%s: %s", corpus_dir, strerror(errno));
    folders f = make_folders();
    char *name = rt_test_join(f.scene_dir, "fuzz.obj"),
          *mtl = rt_test_join(f.scene_dir,
                                                            "m.mtl");
    rt_load_options options;
    rt_load_options_init(&options);
    options.width = options.height = 16;
    options.resolve = rt_resolve_in_folder;
    int files = 0;
    struct dirent *entry;
    while ((entry = readdir(dir)) != NULL) {
        if (entry->d_name[0] == '.')
            continue;
        char *path = rt_test_join(corpus_dir, entry->d_name);
        size_t size;
        char *text = rt_test_read_file(path, &size);
        ck_assert_ptr_nonnull(text);
        char *marker = strstr(text, "\n#mtl\n");
        unlink(mtl);
        if (marker != NULL) {
            rt_test_write_bytes(mtl, marker + 6,
                                size - (size_t)(marker + 6 - text));
            size = (size_t)(marker - text) + 1;
        }
        rt_scene *scene = (rt_scene *)1;
        rt_error error;
        memset(&error, 0, sizeof error);
        rt_status status =
            rt_scene_parse(text, size, name, &options, &scene, &error);
        if (status == RT_OK) {
            rt_scene_info info = {.size = sizeof info};
            rt_scene_get_info(scene, &info);
            for (int i = 0; i < info.facet_count; i++) {
                rt_facet_info facet = {.size = sizeof facet};
                rt_scene_facet(scene, i, &facet);
                ck_assert_msg(facet.degenerate != RT_FACET_ZERO_AREA,
                              "%s: a facet without area", entry->d_name);
            }
            ck_assert_int_eq(rt_test_count_warnings(scene, "root:"), 0);
            rt_scene_destroy(scene);
        } else {
            ck_assert_ptr_null(scene);
            ck_assert_msg(error.message[0] != '\0', "%s", entry->d_name);
        }
        free(text);
        free(path);
        files++;
    }
    closedir(dir);
    ck_assert_int_ge(files, 15);
    unlink(mtl);
    free(mtl);
    free(name);
    free(corpus_dir);
    remove_folders(&f);
}
END_TEST

static Suite *obj_files_suite(void)
{
    Suite *s = suite_create("obj_files");
    TCase *c = tcase_create("resolver");
    tcase_add_test(
        c,
        names_leading_out_of_the_folder_get_one_message_whether_or_not_the_file_exists);
    tcase_add_test(c, links_and_folders_inside_the_folder_are_followed);
    tcase_add_test(c, a_fifo_named_as_a_library_is_refused_without_blocking);
    tcase_add_test(c, a_file_larger_than_the_limit_is_refused_unread);
    tcase_add_test(c, names_in_messages_have_their_control_bytes_escaped);
    suite_add_tcase(s, c);
    c = tcase_create("load");
    tcase_add_test(c, one_library_under_a_thousand_spellings_is_read_once);
    tcase_add_test(c, a_resolver_that_gives_more_than_the_budget_is_refused);
    tcase_add_test(
        c, an_obj_naming_itself_as_its_library_is_read_once_and_not_quoted);
    tcase_add_test(c, nothing_of_a_library_before_its_first_newmtl_is_quoted);
    tcase_add_test(c, a_usemtl_before_its_mtllib_gets_its_material);
    tcase_add_test(c,
                   a_parse_from_memory_reads_a_file_only_through_a_resolver);
    tcase_add_test(
        c, a_scene_file_that_is_a_fifo_still_loads_and_lists_no_identity);
    tcase_add_test(c, a_cancel_flag_raised_before_a_load_cancels_it);
    tcase_add_test(c, the_obj_corpus_replays_without_fault);
    suite_add_tcase(s, c);
    return s;
}

RT_CHECK_MAIN(obj_files_suite)
