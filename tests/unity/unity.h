/* unity.h - rast8's own small test header with Unity's names.
 *
 * The same test sources build against ThrowTheSwitch Unity where it is
 * installed (put its include dir first on the path).  This one is C89,
 * needs no printf and prints through UNITY_OUTPUT_CHAR, so it runs on the
 * host and inside the AVR, 6502 and Z80 simulators.  A failed assertion
 * ends the current test (longjmp, as Unity does).  UNITY_END() prints the
 * closing line "N passed, N failed" and returns the number failed.
 */
#ifndef UNITY_H
#define UNITY_H

#include <setjmp.h>

#ifndef UNITY_OUTPUT_CHAR
#include <stdio.h>
#define UNITY_OUTPUT_CHAR(c) putchar(c)
#endif

void setUp(void);
void tearDown(void);

void unity_begin(const char *file);
int unity_end(void);
void unity_run(void (*fn)(void), const char *name, int line);
void unity_fail(int line, const char *msg);
void unity_fail_int(int line, const char *msg, long expected, long actual);
void unity_assert_mem(const void *e, const void *a, unsigned len, int line);
void unity_print(const char *s);
void unity_print_long(long v);
extern jmp_buf unity_abort;

#define UNITY_BEGIN() unity_begin(__FILE__)
#define UNITY_END() unity_end()
#define RUN_TEST(fn) unity_run(fn, #fn, __LINE__)
#define TEST_PASS() longjmp(unity_abort, 2)
#define TEST_FAIL_MESSAGE(m) unity_fail(__LINE__, m)
#define TEST_FAIL() unity_fail(__LINE__, "failed")
#define TEST_MESSAGE(m) (unity_print(m), unity_print("\n"))

#define TEST_ASSERT_MESSAGE(c, m) do { if (!(c)) unity_fail(__LINE__, m); } while (0)
#define TEST_ASSERT(c) TEST_ASSERT_MESSAGE(c, "expected true: " #c)
#define TEST_ASSERT_TRUE(c) TEST_ASSERT_MESSAGE(c, "expected true: " #c)
#define TEST_ASSERT_FALSE(c) TEST_ASSERT_MESSAGE(!(c), "expected false: " #c)
#define TEST_ASSERT_TRUE_MESSAGE(c, m) TEST_ASSERT_MESSAGE(c, m)
#define TEST_ASSERT_NULL(p) TEST_ASSERT_MESSAGE((p) == 0, "expected NULL: " #p)
#define TEST_ASSERT_NOT_NULL(p) TEST_ASSERT_MESSAGE((p) != 0, "expected non-NULL: " #p)

#define UNITY_CMP(e, a, op, m) do { long ue_ = (long)(e), ua_ = (long)(a); \
    if (!(ua_ op ue_)) unity_fail_int(__LINE__, m, ue_, ua_); } while (0)
#define TEST_ASSERT_EQUAL_INT(e, a) UNITY_CMP(e, a, ==, #a)
#define TEST_ASSERT_EQUAL_INT8(e, a) UNITY_CMP(e, a, ==, #a)
#define TEST_ASSERT_EQUAL_INT16(e, a) UNITY_CMP(e, a, ==, #a)
#define TEST_ASSERT_EQUAL_INT32(e, a) UNITY_CMP(e, a, ==, #a)
#define TEST_ASSERT_EQUAL_UINT(e, a) UNITY_CMP(e, a, ==, #a)
#define TEST_ASSERT_EQUAL_UINT8(e, a) UNITY_CMP(e, a, ==, #a)
#define TEST_ASSERT_EQUAL_UINT16(e, a) UNITY_CMP(e, a, ==, #a)
#define TEST_ASSERT_EQUAL_UINT32(e, a) UNITY_CMP(e, a, ==, #a)
#define TEST_ASSERT_EQUAL_HEX8(e, a) UNITY_CMP(e, a, ==, #a)
#define TEST_ASSERT_EQUAL_HEX16(e, a) UNITY_CMP(e, a, ==, #a)
#define TEST_ASSERT_EQUAL(e, a) UNITY_CMP(e, a, ==, #a)
#define TEST_ASSERT_EQUAL_INT_MESSAGE(e, a, m) UNITY_CMP(e, a, ==, m)
#define TEST_ASSERT_NOT_EQUAL(e, a) UNITY_CMP(e, a, !=, #a)
/* Unity's order: threshold first, then the actual value. */
#define TEST_ASSERT_LESS_OR_EQUAL(t, a) UNITY_CMP(t, a, <=, #a " <= threshold")
#define TEST_ASSERT_GREATER_OR_EQUAL(t, a) UNITY_CMP(t, a, >=, #a " >= threshold")
#define TEST_ASSERT_LESS_THAN(t, a) UNITY_CMP(t, a, <, #a " < threshold")
#define TEST_ASSERT_GREATER_THAN(t, a) UNITY_CMP(t, a, >, #a " > threshold")
#define TEST_ASSERT_INT_WITHIN(d, e, a) do { long ud_ = (long)(a) - (long)(e); \
    if (ud_ < -(long)(d) || ud_ > (long)(d)) unity_fail_int(__LINE__, "not within delta: " #a, (long)(e), (long)(a)); } while (0)
#define TEST_ASSERT_EQUAL_MEMORY(e, a, n) unity_assert_mem(e, a, (unsigned)(n), __LINE__)

#endif
