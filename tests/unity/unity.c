/* unity.c - see unity.h.  C89, no printf. */
#include "unity.h"

jmp_buf unity_abort;
static const char *u_file;
static const char *u_name;
static unsigned u_passed, u_failed;
static int u_cur_failed;

void unity_print(const char *s)
{
    while (*s) {
        UNITY_OUTPUT_CHAR(*s);
        s++;
    }
}

void unity_print_long(long v)
{
    char d[12];
    int n = 0;
    unsigned long u;
    if (v < 0) {
        UNITY_OUTPUT_CHAR('-');
        u = (unsigned long)(-(v + 1)) + 1u;
    } else {
        u = (unsigned long)v;
    }
    do {
        d[n++] = (char)('0' + (int)(u % 10u));
        u /= 10u;
    } while (u);
    while (n)
        UNITY_OUTPUT_CHAR(d[--n]);
}

void unity_begin(const char *file)
{
    u_file = file;
    u_passed = u_failed = 0;
}

static void fail_head(int line)
{
    unity_print(u_file);
    UNITY_OUTPUT_CHAR(':');
    unity_print_long(line);
    UNITY_OUTPUT_CHAR(':');
    if (u_name)           /* no ?: here: cc65 2.19 rejects it */
        unity_print(u_name);
    else
        unity_print("?");
    unity_print(":FAIL: ");
}

void unity_fail(int line, const char *msg)
{
    fail_head(line);
    unity_print(msg);
    UNITY_OUTPUT_CHAR('\n');
    u_cur_failed = 1;
    longjmp(unity_abort, 1);
}

void unity_fail_int(int line, const char *msg, long expected, long actual)
{
    fail_head(line);
    unity_print(msg);
    unity_print(" expected ");
    unity_print_long(expected);
    unity_print(" was ");
    unity_print_long(actual);
    UNITY_OUTPUT_CHAR('\n');
    u_cur_failed = 1;
    longjmp(unity_abort, 1);
}

void unity_assert_mem(const void *e, const void *a, unsigned len, int line)
{
    const unsigned char *pe = (const unsigned char *)e;
    const unsigned char *pa = (const unsigned char *)a;
    unsigned i;
    for (i = 0; i < len; i++) {
        if (pe[i] != pa[i]) {
            fail_head(line);
            unity_print("memory differs at byte ");
            unity_print_long((long)i);
            unity_print(" expected ");
            unity_print_long(pe[i]);
            unity_print(" was ");
            unity_print_long(pa[i]);
            UNITY_OUTPUT_CHAR('\n');
            u_cur_failed = 1;
            longjmp(unity_abort, 1);
        }
    }
}

void unity_run(void (*fn)(void), const char *name, int line)
{
    (void)line;
    u_name = name;
    u_cur_failed = 0;
    if (setjmp(unity_abort) == 0) {
        setUp();
        fn();
    }
    if (setjmp(unity_abort) == 0)
        tearDown();
    if (u_cur_failed)
        u_failed++;
    else
        u_passed++;
}

int unity_end(void)
{
    unity_print_long((long)u_passed);
    unity_print(" passed, ");
    unity_print_long((long)u_failed);
    unity_print(" failed\n");
    return (int)u_failed;
}
