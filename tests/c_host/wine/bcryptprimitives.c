/* Test-only stand-in for Windows 10's bcryptprimitives.dll, which Wine 8 lacks: Rust's standard library
 * imports ProcessPrng from it (random keys of hash maps). Placed beside the host executable under Wine,
 * never shipped. RtlGenRandom (advapi32's SystemFunction036) fills the buffer instead. */
#include <windows.h>

BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length) {
    while (length > 0) {
        ULONG chunk = length > 0x10000000 ? 0x10000000 : (ULONG)length;
        if (!SystemFunction036(data, chunk)) return FALSE;
        data += chunk;
        length -= chunk;
    }
    return TRUE;
}
