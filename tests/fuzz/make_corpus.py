#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets (tests/fuzz/corpus/<target>/): valid frames of
each protocol, edge cases and known-bad inputs. Run from anywhere; the output is committed."""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def crc16_ccitt_false(data: bytes) -> int:
    crc = 0xFFFF
    for b in data:
        crc ^= b << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1021) & 0xFFFF if crc & 0x8000 else (crc << 1) & 0xFFFF
    return crc


assert crc16_ccitt_false(b"123456789") == 0x29B1  # CRC catalogue check value


def write(target: str, name: str, data: bytes) -> None:
    folder = os.path.join(HERE, "corpus", target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


# --- gauge_ascii -------------------------------------------------------------------------
for name, text in {
    "reading": b"01A+00026.812\r",
    "negative": b"01A-0000.123\r",
    "inch_five_decimals": b"01A+00.12345\r",
    "suffix_mm": b"01A+00026.812mm\r",
    "suffix_in_space": b"02B+001.0556 in\r\n",
    "three_lines": b"01A+00026.812\r01A+00026.813\r\n01A+00026.814\r",
    "bad_sign": b"01A*00026.812\r",
    "two_points": b"01A+000.26.812\r",
    "letters": b"01A+0X026.812\r",
    "overlong": b"01A+" + b"9" * 60 + b"\r01A+00026.812\r",
    "no_cr": b"01A+00026.812",
    "binary": bytes(range(256)),
}.items():
    write("gauge_ascii", name, text)

# --- digimatic (first byte: 0 raw nibbles, 1 hex text) ----------------------------------
def nibbles(hexstr: str) -> bytes:
    return bytes(int(c, 16) for c in hexstr)


for name, hexstr in {
    "lsm6200_example": "FFFF021076540",
    "projector_negative": "FFFF801234530",
    "inch": "FFFF001055641",
    "judgement_go": "FFFF002681233",
}.items():
    write("digimatic", "raw_" + name, b"\x00" + nibbles(hexstr))
    write("digimatic", "hex_" + name, b"\x01" + hexstr.encode() + b"\r")
write("digimatic", "raw_noise_then_frame", b"\x00\x03\x07\x0f\x0f\x41" + nibbles("FFFF0021") + nibbles("FFFF002681230"))
write("digimatic", "raw_five_f", b"\x00\x0f" + nibbles("FFFF002681230"))
write("digimatic", "raw_bad_digit", b"\x00" + nibbles("FFFF002A81230"))
write("digimatic", "hex_short_and_long", b"\x01FFFF00268123\rFFFF0026812300\rffff801234530\r")

# --- probe_frames ------------------------------------------------------------------------
def frame(seq: int, typ: int, payload: bytes) -> bytes:
    body = bytes([len(payload), seq & 0xFF, typ]) + payload
    return b"\xa5" + body + struct.pack("<H", crc16_ccitt_false(body))


def sample(t_us: int, adc0: int, adc1: int, d0_nm: int, d1_nm: int, status: int) -> bytes:
    return struct.pack("<IiiiiH", t_us, adc0, adc1, d0_nm, d1_nm, status)


samples = b"".join(frame(i, 0x01, sample(i * 5000, 36600, 31760, 20000, -5000, 0x11)) for i in range(5))
write("probe_frames", "samples", samples)
write("probe_frames", "ack_begin", frame(0, 0x02, struct.pack("<BBI", 0x14, 0, 0)))
write("probe_frames", "ack_chunk", frame(1, 0x02, struct.pack("<BBI", 0x15, 0, 128)))
write("probe_frames", "ack_crc_mismatch", frame(2, 0x02, struct.pack("<BBI", 0x16, 5, 0)))
write("probe_frames", "table_info", frame(3, 0x03, struct.pack("<HHIB", 7, 0xBEEF, 1000, 1)))
write("probe_frames", "handshake_replies",
      frame(0, 0x03, struct.pack("<HHIB", 1, 0x1234, 64, 1)) + frame(1, 0x02, struct.pack("<BBI", 0x12, 0, 200))
      + frame(2, 0x02, struct.pack("<BBI", 0x10, 0, 0)) + samples)
corrupt = bytearray(samples)
corrupt[10] ^= 0x40
write("probe_frames", "corrupt_middle", bytes(corrupt))
write("probe_frames", "lost_and_duplicate",
      frame(10, 0x01, sample(0, 1, 2, 3, 4, 1)) + frame(10, 0x01, sample(0, 1, 2, 3, 4, 1))
      + frame(14, 0x01, sample(1, 1, 2, 3, 4, 1)) + frame(13, 0x01, sample(2, 1, 2, 3, 4, 1)))
write("probe_frames", "bad_length", b"\x00\xa5\xff\x13\x55" + frame(3, 0x01, sample(0, 0, 0, 0, 0, 0)))
write("probe_frames", "short_payloads", frame(0, 0x01, b"\x01\x02") + frame(1, 0x02, b"") + frame(2, 0x7F, b"xyz"))
write("probe_frames", "overrange_excitation",
      frame(0, 0x01, sample(0, 0, 65535, 0, 0, 0x07)) + frame(1, 0x01, sample(0, 1, 1, 0, 0, 0x08)))

# --- modbus_registers (type, word order, scale index, then big-endian words) ---------------
write("modbus_registers", "int16_negative", bytes([0, 0, 1]) + struct.pack(">H", 0xFFFE))
write("modbus_registers", "uint16", bytes([1, 0, 0]) + struct.pack(">H", 65534))
write("modbus_registers", "int32_high_first", bytes([2, 0, 0]) + struct.pack(">HH", 0x0001, 0x86A0))
write("modbus_registers", "int32_low_first", bytes([2, 1, 3]) + struct.pack(">HH", 0x86A0, 0x0001))
write("modbus_registers", "uint32_max", bytes([3, 0, 0]) + struct.pack(">HH", 0xFFFF, 0xFFFF))
write("modbus_registers", "float_25", bytes([4, 0, 0]) + struct.pack(">HH", 0x41C8, 0x0000))
write("modbus_registers", "float_nan", bytes([4, 0, 0]) + struct.pack(">HH", 0x7FC0, 0x0000))
write("modbus_registers", "float_huge_scale", bytes([4, 0, 6]) + struct.pack(">HH", 0x7F7F, 0xFFFF))
write("modbus_registers", "map", bytes([2, 7, 1]) + bytes([1, 0, 10, 0, 1, 0, 12, 4, 1, 0, 200, 2, 0, 0xFF, 0xFF, 2]))
# --- bounded_input (max lines % 16, max line length % 64, max bytes, then the text) -----------
write("bounded_input", "within", bytes([4, 20, 200]) + b"x_mm,error_mm\n0,0.01\n1,0.02\n")
write("bounded_input", "long_line", bytes([4, 8, 200]) + b"," * 40 + b"\n")
write("bounded_input", "many_lines", bytes([2, 8, 200]) + b"1\n2\n3\n4\n")
write("bounded_input", "no_limits", bytes([0, 0, 0]) + b"\n\n\r\n")

# --- config_csv (even first byte: profile CSV; odd: deformation experiment CSV) ---------------
write("config_csv", "profile", b"\x00\xef\xbb\xbfx_mm,error_mm\r\n# part 1\r\n0,0.071\r\n25,0.1\r\n50,0.13\r\n")
write("config_csv", "profile_huge", b"\x00x_mm,error_mm\n0,1e308\n1e300,-1e308\n")
write("config_csv", "profile_comma_decimal", b"\x00x_mm,error_mm\n0,5,0,01\n")
write("config_csv", "deformation", b"\x01# preset: feed-scheduling\n# seed: 7\na_mm,f_mm_rev,z_mm,y_um\n"
      b"0.5,0.1,10,12.5\n1.0,0.2,20,30.1\n")
write("config_csv", "deformation_bad", b"\x01a_mm,f_mm_rev,z_mm,y_um\n0.5,0.1,10\nnan,1,2,3\n")
# --- preset_json (even first byte: run-to-run plant and controller; odd: boring scenario) -------
def preset_file(name: str) -> bytes:
    with open(os.path.join(HERE, "..", "..", "resources", "presets", name + ".json"), "rb") as f:
        return f.read()


write("preset_json", "paper_2012", b"\x00" + preset_file("paper-2012"))
write("preset_json", "paper_2012_filter", b"\x00" + preset_file("paper-2012-filter"))
write("preset_json", "heavy_boring", b"\x01" + preset_file("heavy-boring"))
write("preset_json", "many_components", b"\x00" + b'{"plant": {"part_length_mm": 325, "gain": 2, '
      b'"gauge_noise_variance_mm2": 2.5e-7, "disturbance": [' + b",".join([b'{"type": "ar1", "pole": 0.5, '
      b'"variance_mm2": 1e-5}'] * 20) + b"]}}")
write("preset_json", "boring_slow", b"\x01" + b'{"tool": {"id": "t", "section": "round", "diameter_mm": 40, '
      b'"overhang_mm": 200}, "cut": {"bore_length_mm": 5000, "feed_mm_per_rev": 0.01, "spindle_rpm": 1}}')

# --- preset_sections (first byte % 7 picks the reader; see fuzz_preset_sections.cpp) ------------
write("preset_sections", "corner", b"\x00" + preset_file("1v340-feed-drives"))
write("preset_sections", "corner_net_header", b"\x01" + b'{"format": "trueturn-corrective-net", "network": {}}')
write("preset_sections", "deformation_model", b"\x02" + b'{"kind": "trueturn-deformation-model", "format": 1, '
      b'"factors": {"a_mm": {"centre": 1.25, "half_range": 0.75, "min": 0.5, "max": 2}, '
      b'"f_mm_rev": {"centre": 0.2, "half_range": 0.1, "min": 0.1, "max": 0.3}, '
      b'"z_mm": {"centre": 200, "half_range": 200, "min": 0, "max": 400}}, '
      b'"terms": [{"term": "1", "powers": [0, 0, 0], "coefficient_um": 40, "std_error_um": 0.1, "t": 400}, '
      b'{"term": "a", "powers": [1, 0, 0], "coefficient_um": 20, "std_error_um": 0.1, "t": 200}]}')
write("preset_sections", "feed_scheduling", b"\x03" + preset_file("feed-scheduling"))
write("preset_sections", "hydraulic_feed", b"\x04" + preset_file("hydraulic-feed"))
write("preset_sections", "lathe_group1", b"\x05" + preset_file("paper-2012-group1"))
write("preset_sections", "systematic_group2", b"\x06" + preset_file("paper-2012-group2"))
write("preset_sections", "systematic_huge", b"\x06" + b'{"systematic_model": {"part_length_mm": 325, '
      b'"coefficients": [1e300, 0, 0]}}')

# --- linuxcnc_reply (first byte: where the stream is cut in two chunks) ----------------------------
# Recorded from linuxcncrsh of the Debian 12 package (scripts/start-test-linuxcnc.sh), line ends as sent.
for name, text in {
    "handshake": b"\x05HELLO ACK EMCNETSVR 1.1\r\nset echo off\r\nSET VERBOSE ACK\n\rSET ENABLE ACK\n\r",
    "status": b"\x11ESTOP OFF\r\nMACHINE ON\r\nMODE MDI\r\nPROGRAM_STATUS IDLE\r\nJOINT_HOMED YES YES NO NO NO NO\r\n",
    "position": b"\x20ABS_ACT_POS 0.531496 0.000000 -0.293701 0.000000 0.000000 0.000000\r\n",
    "units": b"\x00USER_LINEAR_UNITS INCH\r\nPROGRAM_UNITS MM\r\n",
    "naks": b"\x03SET MDI NAK\n\rGET NONSENSE NAK\r\n\r\nHELLO NAK\r\n",
    "error": b"\x07ERROR Can't issue MDI command when not homed\r\nOPERATOR_DISPLAY OK\r\n",
    "debug": b"\x09OPERATOR_DISPLAY TRUETURN1 0.012300 -0.004000\r\n",
    "cut_off": b"\x30ABS_ACT_POS 0.531496 0.000000 -0.29",
    "binary": b"\x02ESTOP O\x01N\r\n",
    "out_of_step": b"\x01SET (DEBUG,Q3 NAK\n\r",
    "overlong": b"\x01OPERATOR_DISPLAY " + b"9" * 100 + b"\r\n",
}.items():
    write("linuxcnc_reply", name, text)

print("corpora written under", os.path.join(HERE, "corpus"))
