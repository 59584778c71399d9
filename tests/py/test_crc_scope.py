"""docs/protocol.md section 1: the scope of CRC-16/CCITT-FALSE's HD 4.
0x11021 = (x + 1) * p(x), p primitive of degree 15 (period 32767): every
odd-weight error is caught, two-bit errors are caught iff they are less
than 32767 bits apart, so HD 4 holds for bodies up to 4093 bytes."""
from rast8.codec import crc16

POLY = 0x11021


def _mod(a, m):
    dm = m.bit_length() - 1
    while a.bit_length() - 1 >= dm:
        a ^= m << (a.bit_length() - 1 - dm)
    return a


def test_polynomial_factors_and_period():
    # (x + 1) divides the generator: x = 1 is a root (even number of terms)
    assert bin(POLY).count("1") % 2 == 0
    # the other factor: POLY / (x + 1)
    q, r, a = 0, POLY, POLY
    while a.bit_length() > 1:
        sh = a.bit_length() - 2
        q |= 1 << sh
        a ^= 0b11 << sh
    assert a == 0
    p = q
    assert p.bit_length() - 1 == 15
    # x^k mod p returns to 1 first at k = 32767: p is primitive
    x, k = 2, 1
    while x != 1:
        x = _mod(x << 1, p)
        k += 1
    assert k == 32767


def _flip(data, *bits):
    b = bytearray(data)
    for i in bits:
        b[i // 8] ^= 0x80 >> (i % 8)
    return bytes(b)


def test_two_bit_errors_32767_apart_pass_only_in_long_packets():
    body = bytes((i * 37 + 11) & 0xFF for i in range(4100))     # longer than 4093 bytes
    c = crc16(body)
    assert crc16(_flip(body, 5, 5 + 32767)) == c                # undetected
    assert crc16(_flip(body, 5, 5 + 32766)) != c
    assert crc16(_flip(body, 5, 5 + 32767, 9)) != c             # odd weight: always caught
    # in a 4093-byte body no two flipped bits are 32767 apart (with the
    # 16 CRC bits the codeword is 32760 bits), so all 2-bit errors are caught
    assert 4093 * 8 + 16 <= 32767 < 4094 * 8 + 16 + 8
