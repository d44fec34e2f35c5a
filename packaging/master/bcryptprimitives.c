/* Test-only stand-in for Windows' bcryptprimitives.dll, which wine 8 does not have.
 *
 * Rust's standard library on Windows 10 and later takes its random numbers (for HashMap seeds)
 * from ProcessPrng in bcryptprimitives.dll. Every supported Windows has that DLL; wine 8, which
 * the tests use to run the win64 binary on Linux, does not. This DLL exports ProcessPrng on top
 * of RtlGenRandom (advapi32's SystemFunction036) and is placed beside the test master only. It is
 * never shipped in the FMU.
 */
#include <windows.h>

BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

__declspec(dllexport) BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length) {
    while (length > 0) {
        ULONG chunk = length > 0x10000000 ? 0x10000000 : (ULONG)length;
        if (!SystemFunction036(data, chunk)) return FALSE;
        data += chunk;
        length -= chunk;
    }
    return TRUE;
}
