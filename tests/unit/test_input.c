/* test_input.c - the interpreter: comments, continuation, quotes, substitution,
 * tokenizing, flow (label/jump/next, include, quit), print/log/echo, and the
 * error text and line number of each kind of bad input. */
#include <stdlib.h>
#include <unistd.h>

#include "test.h"

#include "command.h"
#include "error.h"
#include "variable.h"

/* Engine whose screen output goes to a memory buffer. */
struct cap {
    struct gravel *g;
    char *buf;
    size_t len;
};

static void cap_open(struct cap *c)
{
    c->g = test_engine();
    c->buf = NULL;
    c->len = 0;
    c->g->screen = open_memstream(&c->buf, &c->len);
}

/* Run text; returns rc; the screen output so far is in c->buf. */
static int cap_run(struct cap *c, const char *text)
{
    int rc = test_script(c->g, text);
    fflush(c->g->screen);
    return rc;
}

static void cap_close(struct cap *c)
{
    fclose(c->g->screen);
    c->g->screen = NULL;
    gr_destroy(c->g);
    free(c->buf);
}

/* Check that running `text` prints exactly `want` and succeeds. */
#define CHECK_OUTPUT(text, want)                                                    \
    do {                                                                            \
        struct cap c_;                                                              \
        cap_open(&c_);                                                              \
        int rc_ = cap_run(&c_, text);                                               \
        if (rc_ != GR_OK || strcmp(c_.buf, want) != 0) {                            \
            printf("  check failed %s:%d: rc %d, output '%s', expected '%s' (%s)\n",\
                   __FILE__, __LINE__, rc_, c_.buf, want, c_.g->err.msg);           \
            t_failed_checks++;                                                      \
        }                                                                           \
        cap_close(&c_);                                                             \
    } while (0)

static char tmpdir[64];

static char *tmp_path(const char *name)
{
    static char buf[4][128];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", tmpdir, name);
    return buf[k];
}

static void write_file(const char *path, const char *text)
{
    FILE *fp = fopen(path, "w");
    fputs(text, fp);
    fclose(fp);
}

static char *read_file(const char *path)
{
    FILE *fp = fopen(path, "r");
    if (!fp)
        return NULL;
    char *buf = NULL;
    size_t cap = 0;
    ssize_t n = getdelim(&buf, &cap, '\0', fp);
    fclose(fp);
    if (n < 0) {
        free(buf);
        return calloc(1, 1);
    }
    return buf;
}

TEST(comments)
{
    CHECK_OUTPUT("# a comment line\nprint hi # trailing\n", "hi\n");
    CHECK_OUTPUT("print \"a # not a comment\"   # comment\n", "a # not a comment\n");
    CHECK_OUTPUT("print 'x#y'\n", "x#y\n");
    CHECK_OUTPUT("print \"\"\"p # q\"\"\"\n", "p # q\n");
    CHECK_OUTPUT("   \n\t\n#\nprint ok\n", "ok\n");
}

TEST(continuation)
{
    CHECK_OUTPUT("print &\n  \"joined\"\n", "joined\n");
    CHECK_OUTPUT("print \"a &\n b\"\n", "a  b\n");
    CHECK_OUTPUT("print &   \n   x\n", "x\n");       /* spaces after & are allowed */
    CHECK_OUTPUT("print & # a comment after & stops the continuation\nprint y\n", "&\ny\n");
    /* trailing & on the last line just ends the command */
    CHECK_OUTPUT("print last &", "last\n");
    /* line numbers count physical lines: the bad command starts on line 4 */
    CHECK_ERROR("variable v string &\n &\n b\nbogus\n", "unknown command 'bogus'", 4);
    /* CRLF line ends */
    CHECK_OUTPUT("print crlf\r\nprint two\r\n", "crlf\ntwo\n");
}

TEST(quotes)
{
    CHECK_OUTPUT("print \"two words\"\n", "two words\n");
    CHECK_OUTPUT("print 'single \"inner\"'\n", "single \"inner\"\n");
    CHECK_OUTPUT("print \"\"\"\nl1\nl2\n\"\"\"\n", "\nl1\nl2\n\n");
    CHECK_OUTPUT("print \"\"\"has 'single' and \"double\" \"\"\"\n",
                 "has 'single' and \"double\" \n");
    /* an apostrophe inside a word is literal */
    CHECK_OUTPUT("print it's\n", "it's\n");
    /* quoted words keep their spaces as one argument */
    CHECK_OUTPUT("variable v index \"a b\" 'c  d' \"\"\"e\"\"\"\nlabel l\nprint \"[$v]\"\n"
                 "next v\njump SELF l\n",
                 "[a b]\n[c  d]\n[e]\n");
    CHECK_OUTPUT("print \"\"\n", "\n");
}

TEST(substitution)
{
    CHECK_OUTPUT("variable a equal 2^3\nprint \"${a} $a\"\n", "8 8\n");
    CHECK_OUTPUT("variable a equal 2^3\nprint $a\n", "8\n");
    CHECK_OUTPUT("print $(1/3)\n", "0.33333333333333331483\n"); /* %.20g default */
    CHECK_OUTPUT("print $(1/3:%.3f)\n", "0.333\n");
    CHECK_OUTPUT("print \"$(2*(3+4):%8.2e)\"\n", "1.40e+01\n");
    CHECK_OUTPUT("variable name string world\nprint \"hello ${name}!\"\n", "hello world!\n");
    /* $xx is variable x followed by x */
    CHECK_OUTPUT("variable x string Q\nprint $xx\n", "Qx\n");
    /* a variable can supply several words, even the command itself */
    CHECK_OUTPUT("variable w string \"print hi\"\n${w}\n", "hi\n");
    /* substituted text is not scanned again; a string variable substitutes
     * its text at its definition except what is quoted inside it (LAMMPS;
     * lmp 29Sep2021 prints the same) */
    CHECK_OUTPUT("variable s string \"'$x'\"\nprint \"${s}\"\n", "'$x'\n");
    CHECK_OUTPUT("variable a string A\nvariable t string '${a}'\nvariable a string B\n"
                 "print ${t}\n",
                 "A\n");
    /* loop pad */
    CHECK_OUTPUT("variable i loop 9 10 pad\nprint $i\nnext i\nprint $i\n", "09\n10\n");
}

TEST(long_lines)
{
    /* a 1 MB line, and a 1 MB variable value, with no fixed buffers */
    size_t n = 1 << 20;
    char *text = malloc(n + 64);
    strcpy(text, "print \"");
    memset(text + 7, 'x', n);
    strcpy(text + 7 + n, "\"\n");
    struct cap c;
    cap_open(&c);
    CHECK(cap_run(&c, text) == GR_OK);
    CHECK(c.len == n + 1);
    cap_close(&c);

    strcpy(text, "variable big string ");
    memset(text + 20, 'y', n);
    strcpy(text + 20 + n, "\nprint \"${big}${big}\"\n");
    cap_open(&c);
    CHECK(cap_run(&c, text) == GR_OK);
    CHECK(c.len == 2 * n + 1);
    cap_close(&c);

    /* a 1 MB line of many words */
    char *p = text;
    p += sprintf(p, "variable many index");
    while ((size_t)(p - text) < n - 8)
        p += sprintf(p, " w%d", (int)(p - text) % 1000);
    strcpy(p, "\nprint $(1+1)\n");
    CHECK_OUTPUT(text, "2\n");
    free(text);
}

TEST(loops)
{
    CHECK_OUTPUT("variable i loop 3\nlabel top\nprint \"i=$i\"\nnext i\njump SELF top\n"
                 "print done\n",
                 "i=1\ni=2\ni=3\ndone\n");
    /* nested loops with two labels */
    CHECK_OUTPUT("variable a loop 2\nlabel outer\nvariable b loop 2\nlabel inner\n"
                 "print \"$a$b\"\nnext b\njump SELF inner\nnext a\njump SELF outer\n",
                 "11\n12\n21\n22\n");
    /* lines skipped while searching a label are not substituted */
    CHECK_OUTPUT("variable n loop 1\njump SELF skip\nprint \"${undefined}\"\nlabel skip\n"
                 "print after\n",
                 "after\n");
    /* next with several variables: the loop ends with the shortest */
    CHECK_OUTPUT("variable a index x y z\nvariable b index 1 2\nlabel l\nprint $a$b\n"
                 "next a b\njump SELF l\nprint ${a}\n",
                 "x1\ny2\nz\n");
}

TEST(loop_exhausted_deleted)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "variable i loop 2\nlabel t\nnext i\njump SELF t\n") == GR_OK);
    CHECK(var_retrieve(g, "i") == NULL);
    gr_destroy(g);
}

TEST(include_and_jump_file)
{
    write_file(tmp_path("inc.in"), "variable fromfile equal 40+2\nprint \"in include\"\n");
    char script[512];
    snprintf(script, sizeof script, "include %s\nprint \"after ${fromfile}\"\n",
             tmp_path("inc.in"));
    CHECK_OUTPUT(script, "in include\nafter 42\n");

    /* jump FILE label: continue in another file at a label */
    write_file(tmp_path("b.in"), "print b1\nlabel here\nprint b2\n");
    snprintf(script, sizeof script, "print a1\njump %s here\nprint never\n", tmp_path("b.in"));
    CHECK_OUTPUT(script, "a1\nb2\n");

    /* errors inside an include name the included file and its line */
    write_file(tmp_path("bad.in"), "print ok\n\nnosuchcmd\n");
    snprintf(script, sizeof script, "include %s\n", tmp_path("bad.in"));
    struct gravel *g = test_engine();
    CHECK(test_script(g, script) == GR_ERR);
    CHECK(strstr(g->err.msg, "unknown command 'nosuchcmd'") != NULL);
    CHECK(strstr(g->err.msg, "bad.in:3)") != NULL);
    gr_destroy(g);

    CHECK_ERROR("print x\ninclude /nonexistent/file.in\n", "cannot open input script", 2);
    CHECK_ERROR("jump /nonexistent/x.in\n", "cannot open input script", 1);
    /* jump SELF on a real file */
    write_file(tmp_path("self.in"), "variable k loop 2\nlabel a\nprint k$k\nnext k\n"
                                    "jump SELF a\n");
    struct cap c;
    cap_open(&c);
    CHECK(inp_file(c.g, tmp_path("self.in")) == GR_OK);
    fflush(c.g->screen);
    CHECK(strcmp(c.buf, "k1\nk2\n") == 0);
    cap_close(&c);
}

TEST(print_file)
{
    char script[512];
    const char *f = tmp_path("p.txt");
    snprintf(script, sizeof script,
             "variable v equal 6*7\nprint \"first $v\" file %s\nprint second append %s "
             "screen no\nprint third screen yes\n", f, f);
    CHECK_OUTPUT(script, "first 42\nthird\n");
    char *got = read_file(f);
    CHECK(got && strcmp(got, "first 42\nsecond\n") == 0);
    free(got);
    CHECK_ERROR("print x file /nonexistent/dir/p.txt\n", "cannot open '/nonexistent/dir/p.txt'",
                1);
    CHECK_ERROR("print hello world\n", "unknown keyword 'world'", 1);
    CHECK_ERROR("print x screen maybe\n", "expected yes or no", 1);
    CHECK_ERROR("print x file\n", "keyword 'file' needs 1 value", 1);
}

TEST(log_and_echo)
{
    const char *f = tmp_path("log.txt");
    char script[512];
    snprintf(script, sizeof script, "log %s\nvariable q equal 1+1\nprint \"q=$q\"\n"
             "echo none\nprint hidden_cmd\nlog none\nprint nolog\n", f);
    struct gravel *g = test_engine();
    CHECK(test_script(g, script) == GR_OK);
    CHECK(g->logfile == NULL);
    char *got = read_file(f);
    CHECK(got && strncmp(got, "gravel (", 8) == 0);
    CHECK(got && strstr(got, "variable q equal 1+1\n"));  /* echoed to log by default */
    CHECK(got && strstr(got, "q=2\n"));
    CHECK(got && strstr(got, "hidden_cmd\n") && !strstr(got, "print hidden_cmd"));
    CHECK(got && !strstr(got, "nolog"));
    free(got);
    gr_destroy(g);
    /* log append keeps the old text */
    snprintf(script, sizeof script, "log %s append\nprint more\n", f);
    g = test_engine();
    CHECK(test_script(g, script) == GR_OK);
    gr_destroy(g);
    got = read_file(f);
    CHECK(got && strstr(got, "q=2\n") && strstr(got, "more\n"));
    free(got);
    /* echo screen shows the command and its substituted form */
    CHECK_OUTPUT("echo screen\nvariable z string Z\nprint $z\n",
                 "variable z string Z\nprint $z\nprint Z\nZ\n");
    CHECK_ERROR("echo loud\n", "expected none, screen, log or both", 1);
    CHECK_ERROR("log /nonexistent/dir/log.txt\n", "cannot open log file", 1);
    CHECK_ERROR("log a.txt sometimes\n", "unknown keyword 'sometimes'", 1);
}

TEST(error_report_has_line)
{
    /* the reported error goes to the log with the offending line under it */
    struct gravel *g = test_engine();
    char *buf = NULL;
    size_t len = 0;
    g->logfile = open_memstream(&buf, &len);
    /* equal-style variables are evaluated when used, not when defined */
    CHECK(test_script(g, "print ok\nvariable x equal 1/0  # oops\n") == GR_OK);
    CHECK(test_script(g, "print ${x}\n") == GR_ERR);
    fflush(g->logfile);
    CHECK(strstr(buf, "ERROR: print: division by zero in expression '1/0' (test.in:1)") != NULL);
    gr_destroy(g);
    free(buf);

    g = test_engine();
    buf = NULL;
    g->logfile = open_memstream(&buf, &len);
    CHECK(test_script(g, "print ok\nprint $(1/0)  # oops\nprint never\n") == GR_ERR);
    fflush(g->logfile);
    CHECK(strstr(buf, "ERROR: print: division by zero in expression '1/0' (test.in:2)\n"
                      "  print $(1/0)  # oops\n") != NULL);
    CHECK(strstr(buf, "never") == NULL);
    gr_destroy(g);
    free(buf);
}

TEST(quit)
{
    struct gravel *g = test_engine();
    CHECK(test_script(g, "variable a equal 1\nquit 3\nvariable b equal 2\n") == GR_QUIT);
    CHECK(inp_quit_status(g) == 3);
    CHECK(var_retrieve(g, "b") == NULL);
    /* the engine reads again after a quit */
    CHECK(test_script(g, "variable c equal 5\n") == GR_OK);
    CHECK(var_retrieve(g, "c") != NULL);
    gr_destroy(g);
    CHECK_ERROR("quit 300\n", "exit status must be between 0 and 255", 1);
    CHECK_ERROR("quit x\n", "expected an integer for exit status", 1);
}

TEST(clear_info_ignored)
{
    struct cap c;
    cap_open(&c);
    c.g->dt = 0.123;
    CHECK(cap_run(&c, "variable keep string yes\nclear\nprint ${keep}\ninfo\n") == GR_OK);
    CHECK(c.g->dt != 0.123);
    CHECK(strstr(c.buf, "yes\n") != NULL);
    CHECK(strstr(c.buf, "Atoms: 0") != NULL);
    CHECK(strstr(c.buf, "Box: not yet created") != NULL);
    CHECK(strstr(c.buf, "keep string 'yes'") != NULL);
    CHECK(strstr(c.buf, "  all (0 atoms)") != NULL);
    cap_close(&c);
    CHECK_ERROR("info everything\n", "unknown category 'everything'", 1);

    struct gravel *g = test_engine();
    CHECK(test_script(g, "comm_modify vel yes\ncomm_modify cutoff 2\nnewton off\n"
                         "processors * * *\natom_modify map array\nsuffix gpu\n"
                         "package gpu 1\ncommunicate single\nnewton on\n") == GR_OK);
    CHECK(g->err.nwarn == 6); /* once per ignored command name (processors is real) */
    gr_destroy(g);
    g = test_engine(); /* comm_style is real: tiled lets balance rcb tile the ranks */
    CHECK(test_script(g, "comm_style tiled\ncomm_style brick\n") == GR_OK);
    CHECK(g->err.nwarn == 0);
    gr_destroy(g);
    CHECK_ERROR("comm_style bogus\n", "comm_style 'bogus' is not brick or tiled", 1);
    CHECK_ERROR("print ok\nshell ls\n", "shell: not supported", 2);
}

TEST(errors)
{
    CHECK_ERROR("print ok\nprnt hello\n", "unknown command 'prnt' (nearest known command: "
                "'print')", 2);
    CHECK_ERROR("echo\n", "echo: expects 1 argument, got 0", 1);
    CHECK_ERROR("quit 1 2\n", "quit: expects at most 1 argument, got 2", 1);
    CHECK_ERROR("variable x\n", "variable: expects at least 2 arguments, got 1", 1);
    CHECK_ERROR("\n\nprint 'unterminated\n", "unterminated single quote", 3);
    CHECK_ERROR("print \"abc\n", "unterminated double quote", 1);
    CHECK_ERROR("print x\nprint \"\"\"never\nclosed\n", "unterminated triple quote", 2);
    CHECK_ERROR("print \"a\"b\n", "closing quote must be followed by white space", 1);
    CHECK_ERROR("print ${nope}\n", "variable 'nope' is not defined (in ${nope})", 1);
    CHECK_ERROR("print $q\n", "variable 'q' is not defined", 1);
    CHECK_ERROR("print ${abc\n", "'${' without a closing '}'", 1);
    CHECK_ERROR("print ${}\n", "empty variable name", 1);
    CHECK_ERROR("print $(1+2\n", "'$(' without a matching ')'", 1);
    CHECK_ERROR("print x$\n", "'$' at the end of the line", 1);
    CHECK_ERROR("print $ x\n", "'$' followed by white space", 1);
    CHECK_ERROR("print $(1:%d)\n", "invalid format '%d'", 1);
    CHECK_ERROR("print $(1/0)\n", "division by zero", 1);
    CHECK_ERROR("print $(v_nope)\n", "variable 'nope' is not defined", 1);
    CHECK_ERROR("jump SELF nolabel\n", "label 'nolabel' not found in test.in", 1);
    CHECK_ERROR("print a\nprint b\njump SELF nolabel\nprint c\n", "jump: label 'nolabel' not "
                "found", 3);
    /* a command name built by substitution is still checked */
    CHECK_ERROR("variable c string bogus\n${c} 1\n", "unknown command 'bogus'", 2);
    /* binary garbage is an error, not a crash */
    CHECK_ERROR("\x01\x02\xff\xfe 1\n", "unknown command", 1);
}

TEST(phase_check)
{
    /* phases are checked centrally for every row that carries one */
    int tested = 0;
    for (const struct command *c = gr_commands; c->name; c++) {
        if (c->phase == PH_ANY)
            continue;
        char text[256];
        int n = snprintf(text, sizeof text, "%s", c->name);
        for (int i = 0; i < c->min_args && n < 200; i++)
            n += snprintf(text + n, sizeof text - (size_t)n, " 1");
        snprintf(text + n, sizeof text - (size_t)n, "\n");
        struct gravel *g = test_engine();
        g->dom.box_exists = c->phase == PH_PRE_BOX;
        CHECK(test_script(g, text) == GR_ERR);
        CHECK(strstr(g->err.msg, c->phase == PH_PRE_BOX ? "must come before the simulation box"
                                                         : "needs a simulation box") != NULL);
        gr_destroy(g);
        tested++;
    }
    printf("  phase_check: %d commands with a phase\n", tested);
}

TEST(stream_and_nested)
{
    /* inp_stream on a FILE, and a script run from inside a command */
    FILE *fp = fmemopen((void *)"variable s string stream\n", 24, "r");
    struct gravel *g = test_engine();
    CHECK(inp_stream(g, fp, "mem") == GR_OK);
    fclose(fp);
    CHECK(var_retrieve(g, "s") && strcmp(var_retrieve(g, "s"), "stream") == 0);
    CHECK(test_script(g, "variable t string outer\n") == GR_OK);
    CHECK(test_script(g, "") == GR_OK);
    gr_destroy(g);
    /* jump SELF on a pipe-like stream cannot rewind */
    int fds[2];
    CHECK(pipe(fds) == 0);
    CHECK(write(fds[1], "label a\njump SELF a\n", 20) == 20);
    close(fds[1]);
    fp = fdopen(fds[0], "r");
    g = test_engine();
    CHECK(inp_stream(g, fp, "pipe") == GR_ERR);
    CHECK(strstr(g->err.msg, "cannot be rewound") != NULL);
    fclose(fp);
    gr_destroy(g);
}

/* issue 24: a command that runs itself through a variable stops at a depth
 * limit with the depth in the message, naming the line that started it */
TEST(nesting_depth)
{
    const char *msg = "commands run by if or run every nested more than 100 deep (does a "
                      "variable expand to a command that runs itself?)";
    char want[256];
    snprintf(want, sizeof want, "if: %s (test.in:3)", msg);
    /* the inner ${c} quoted: a string variable substitutes its unquoted
     * text at its definition (LAMMPS), where c is not defined yet */
    struct gravel *g = test_engine();
    CHECK(test_script(g, "variable c string \"if 1 then ${c}\"\nprint hi\n${c}\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "variable 'c' is not defined") != NULL);
    CHECK(test_script(g, "variable c string \"if 1 then '${c}'\"\nprint hi\n${c}\n") == GR_ERR);
    CHECK(strstr(g->err.msg, want) != NULL);
    /* the counter unwinds with the error: the same engine nests 100 deep again */
    CHECK(test_script(g, "variable k equal 0\n"
                         "variable d string \"if '$k < 100' then 'variable k equal $(v_k+1)' "
                         "'${d}'\"\n${d}\n") == GR_OK);
    CHECK(var_retrieve(g, "k") && !strcmp(var_retrieve(g, "k"), "100"));
    gr_destroy(g);
    CHECK_ERROR("variable c string \"if 1 then '${c}'\"\n\n${c}\n", msg, 3);
    /* one level more than the limit */
    CHECK_ERROR("variable k equal 0\n"
                "variable d string \"if '$k < 101' then 'variable k equal $(v_k+1)' '${d}'\"\n"
                "${d}\n", msg, 3);
    /* a file that includes itself: the error names the file's own line */
    write_file(tmp_path("selfinc.in"), "print x\ninclude selfinc.in\n");
    char cwd[512];
    CHECK(getcwd(cwd, sizeof cwd) != NULL);
    CHECK(chdir(tmpdir) == 0);
    g = test_engine();
    CHECK(test_script(g, "print a\ninclude selfinc.in\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "include: include files nested more than 1000 deep (does a "
                             "file include itself?) (selfinc.in:2)") != NULL);
    gr_destroy(g);
    CHECK(chdir(cwd) == 0);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/gravel-test-input-XXXXXX");
    if (!mkdtemp(tmpdir))
        return 1;
    RUN(comments);
    RUN(continuation);
    RUN(quotes);
    RUN(substitution);
    RUN(long_lines);
    RUN(loops);
    RUN(loop_exhausted_deleted);
    RUN(include_and_jump_file);
    RUN(print_file);
    RUN(log_and_echo);
    RUN(error_report_has_line);
    RUN(quit);
    RUN(clear_info_ignored);
    RUN(errors);
    int nphase = 0;
    for (const struct command *c = gr_commands; c->name; c++)
        nphase += c->phase != PH_ANY;
    if (nphase)
        RUN(phase_check);
    RUN(stream_and_nested);
    RUN(nesting_depth);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    return system(cmd) != 0;
}
