/*
 * jumo-test-peer: an independent Modbus RTU server for the integration tests.
 *
 * The client under test is Qt's; the peer deliberately uses a different
 * implementation (libmodbus) to build replies, so that both sides do not share
 * the same misunderstanding of the protocol.
 *
 * libmodbus 3.1.x filters received RTU frames on a single slave address, so the
 * peer does its own framing and only hands complete, CRC-checked requests to
 * modbus_reply(). That way one process can serve several slaves on one line,
 * log every frame byte for byte and inject faults between framing and reply.
 *
 * With --tcp it is a Modbus TCP gateway instead: libmodbus's TCP server listens,
 * every MBAP request is handed to the slave its unit id names (each with its own
 * registers), and a unit id no slave has gets exception 0x0B (gateway target
 * device failed to respond), as a real gateway answers for a silent device.
 *
 * Usage and the stdin/stdout protocol are described in usage() below.
 */
#define _POSIX_C_SOURCE 200809L

#include <modbus.h>

#include <errno.h>
#include <fcntl.h>
#include <getopt.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <netinet/in.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

/* A pty has no character timing, so the 3.5-character gap of the standard is
 * replaced by a fixed silence that is long enough for socat to relay a whole
 * frame and short enough not to slow down the tests. */
#define FRAME_GAP_MS 5

/* Largest request we accept: 0x10 with a byte count of 255 is 9 + 255 bytes. */
#define MAX_FRAME 300
#define MAX_SLAVES 256
#define NUM_REGS 65536
#define MAX_CLIENTS 8
/* MBAP header (7) + the largest PDU (253). */
#define MAX_ADU 260

enum fault_kind {
    FAULT_NONE,
    FAULT_DROP,
    FAULT_LATE,
    FAULT_STRAY,
    FAULT_BADCRC,
    FAULT_EXCEPTION,
    FAULT_DEAD
};

struct fault {
    enum fault_kind kind;
    unsigned param;  /* milliseconds for late, exception code for exception */
    long remaining;  /* requests left before the fault clears; -1 = until cleared */
};

struct slave {
    modbus_mapping_t mapping;
    uint16_t *regs;
    struct fault fault;
};

static const char *prog = "jumo-test-peer";
static struct slave *slaves[MAX_SLAVES];
static modbus_t *ctx;
static int port_fd = -1;
/* libmodbus writes replies straight to ctx->s. Pointing ctx->s at a pipe while
 * replying lets us see the exact bytes libmodbus produced (for the tx log and
 * for the stray/badcrc faults) before they go out on the line. */
static int capture_rd = -1, capture_wr = -1;
static volatile sig_atomic_t stop_requested;
/* Modbus TCP mode: the listening socket and the connected clients with their
 * receive buffers. */
static int tcp_mode;
static int listen_fd = -1;
static int clients[MAX_CLIENTS];
static uint8_t client_buf[MAX_CLIENTS][2 * MAX_ADU];
static size_t client_len[MAX_CLIENTS];
static unsigned long frames_ok, frames_bad;

static void usage(FILE *out)
{
    fprintf(out,
        "usage: %s --port PATH [--baud 19200] [--format 8N1|8E1|8O1|8N2]\n"
        "          --slave ADDR [--slave ADDR ...] [--set SLAVE:ADDR=WORD[,WORD...]]...\n"
        "       %s --tcp PORT --slave ADDR [--slave ADDR ...] [--set ...]...\n"
        "Numbers are decimal or 0x hex. Each slave has 65536 holding registers,\n"
        "which also serve as its input registers. Address 0 is broadcast.\n"
        "--tcp: a Modbus TCP gateway on 127.0.0.1:PORT (0: a free port, printed as\n"
        "'listening PORT' before 'ready'); the unit id picks the slave, an unknown\n"
        "unit id gets exception 11; faults stray and badcrc do not apply.\n"
        "stdin commands (each answered by 'ok' or 'error: ...'):\n"
        "  fault SLAVE none | drop [COUNT] | late MS [COUNT] | stray [COUNT]\n"
        "              | badcrc [COUNT] | exception CODE [COUNT] | dead\n"
        "  set SLAVE ADDR WORD [WORD...]\n"
        "  get SLAVE ADDR [COUNT]     -> 'regs HHHH HHHH ...'\n"
        "  stats                      -> 'stats rx=N rxbad=N'\n"
        "  quit                       (EOF on stdin quits as well)\n"
        "stdout: 'ready', 'rx HEX', 'rxbad HEX', 'tx HEX', 'ok', 'error: ...'\n"
        "(over TCP, rx shows unit id and PDU, tx the whole MBAP frame)\n",
        prog, prog);
}

static void die(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: ", prog);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    exit(1);
}

/* Tests wait for individual lines, so nothing may linger in a buffer. */
static void out_line(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stdout, fmt, ap);
    va_end(ap);
    fputc('\n', stdout);
    fflush(stdout);
}

static void out_hex(const char *tag, const uint8_t *buf, size_t len)
{
    fputs(tag, stdout);
    fputc(' ', stdout);
    for (size_t i = 0; i < len; i++)
        fprintf(stdout, "%02X", buf[i]);
    fputc('\n', stdout);
    fflush(stdout);
}

static uint16_t crc16(const uint8_t *buf, size_t len)
{
    uint16_t crc = 0xFFFF;
    for (size_t i = 0; i < len; i++) {
        crc ^= buf[i];
        for (int bit = 0; bit < 8; bit++)
            crc = (crc & 1) ? (uint16_t)((crc >> 1) ^ 0xA001) : (uint16_t)(crc >> 1);
    }
    return crc;
}

static int crc_ok(const uint8_t *buf, size_t len)
{
    if (len < 4)
        return 0;
    uint16_t crc = crc16(buf, len - 2);
    return buf[len - 2] == (crc & 0xFF) && buf[len - 1] == (crc >> 8);
}

/* Only "0x" means hex: strtoul's base 0 would read a leading zero as octal,
 * which nobody writing register addresses expects. */
static int parse_num(const char *s, unsigned long max, unsigned long *out)
{
    int base = 10;
    if (s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        base = 16;
        s += 2;
    }
    if (*s == '\0' || *s == '-' || *s == '+')
        return -1;
    char *end;
    errno = 0;
    unsigned long v = strtoul(s, &end, base);
    if (errno || *end != '\0' || v > max)
        return -1;
    *out = v;
    return 0;
}

static int64_t now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000 + ts.tv_nsec / 1000000;
}

static void sleep_ms(unsigned ms)
{
    struct timespec ts = { .tv_sec = ms / 1000, .tv_nsec = (long)(ms % 1000) * 1000000L };
    while (nanosleep(&ts, &ts) == -1 && errno == EINTR)
        ;
}

static void add_slave(unsigned addr)
{
    if (slaves[addr])
        return;
    struct slave *s = calloc(1, sizeof *s);
    uint16_t *regs = s ? calloc(NUM_REGS, sizeof *regs) : NULL;
    if (!regs)
        die("out of memory");
    s->regs = regs;
    /* The mapping is filled in by hand instead of modbus_mapping_new() so that
     * input and holding registers can share one array; the devices being
     * simulated answer 0x03 and 0x04 from the same register space. */
    s->mapping.nb_registers = NUM_REGS;
    s->mapping.tab_registers = regs;
    s->mapping.nb_input_registers = NUM_REGS;
    s->mapping.tab_input_registers = regs;
    slaves[addr] = s;
}

/* The port is non-blocking (libmodbus opens it that way), so a full pty buffer
 * must be waited out rather than losing half a reply. */
static int write_all(int fd, const uint8_t *buf, size_t len)
{
    while (len > 0) {
        ssize_t n = write(fd, buf, len);
        if (n > 0) {
            buf += n;
            len -= (size_t)n;
        } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            fd_set wfds;
            FD_ZERO(&wfds);
            FD_SET(fd, &wfds);
            select(fd + 1, NULL, &wfds, NULL, NULL);
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else {
            return -1;
        }
    }
    return 0;
}

static size_t drain_capture(uint8_t *buf, size_t cap)
{
    size_t len = 0;
    while (len < cap) {
        ssize_t n = read(capture_rd, buf + len, cap - len);
        if (n <= 0)
            break;
        len += (size_t)n;
    }
    return len;
}

/* Runs one libmodbus reply function with ctx->s redirected to the capture pipe
 * and returns the bytes it produced. */
static size_t capture_reply(const uint8_t *req, int req_len, modbus_mapping_t *map,
                            int exception, uint8_t *rsp, size_t cap)
{
    modbus_set_slave(ctx, req[0]);
    modbus_set_socket(ctx, capture_wr);
    int rc = exception ? modbus_reply_exception(ctx, req, (unsigned)exception)
                       : modbus_reply(ctx, req, req_len, map);
    modbus_set_socket(ctx, port_fd);
    if (rc < 0)
        fprintf(stderr, "%s: libmodbus reply failed: %s\n", prog, modbus_strerror(errno));
    return drain_capture(rsp, cap);
}

static size_t build_exception(const uint8_t *req, unsigned code, uint8_t *rsp)
{
    /* libmodbus refuses codes it does not know (>= MODBUS_EXCEPTION_MAX), but
     * the tests need arbitrary ones, so those are framed here. */
    if (code >= 1 && code < MODBUS_EXCEPTION_MAX)
        return capture_reply(req, 0, NULL, (int)code, rsp, MAX_FRAME);
    rsp[0] = req[0];
    rsp[1] = (uint8_t)(req[1] | 0x80);
    rsp[2] = (uint8_t)code;
    uint16_t crc = crc16(rsp, 3);
    rsp[3] = (uint8_t)(crc & 0xFF);
    rsp[4] = (uint8_t)(crc >> 8);
    return 5;
}

/* Returns the exception code a request deserves before it may reach
 * modbus_reply(), or 0. libmodbus itself would answer malformed quantities too,
 * but on that path it sleeps for the response timeout and flushes the port,
 * which would swallow the client's next request. Quantity errors answer 2 as
 * the project's devices do, although the standard suggests 3. */
static unsigned precheck(const uint8_t *req, size_t len)
{
    uint8_t fc = req[1];
    unsigned nb;
    switch (fc) {
    case MODBUS_FC_READ_HOLDING_REGISTERS:
    case MODBUS_FC_READ_INPUT_REGISTERS:
        nb = (unsigned)(req[4] << 8 | req[5]);
        if (nb == 0 || nb > MODBUS_MAX_READ_REGISTERS)
            return MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS;
        return 0;
    case MODBUS_FC_WRITE_SINGLE_REGISTER:
        return 0;
    case MODBUS_FC_WRITE_MULTIPLE_REGISTERS:
        nb = (unsigned)(req[4] << 8 | req[5]);
        if (nb == 0 || nb > MODBUS_MAX_WRITE_REGISTERS)
            return MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS;
        if (req[6] != nb * 2 || len != 9 + (size_t)req[6])
            return MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE;
        return 0;
    default:
        return MODBUS_EXCEPTION_ILLEGAL_FUNCTION;
    }
}

static void handle_broadcast(const uint8_t *req, size_t len)
{
    uint8_t fc = req[1];
    /* A broadcast read has nobody to answer it; malformed writes are ignored
     * because a broadcast never gets an exception either. */
    if (fc != MODBUS_FC_WRITE_SINGLE_REGISTER && fc != MODBUS_FC_WRITE_MULTIPLE_REGISTERS)
        return;
    if (precheck(req, len) != 0)
        return;
    uint8_t junk[MAX_FRAME];
    for (int a = 1; a < MAX_SLAVES; a++) {
        if (slaves[a])
            capture_reply(req, (int)len, &slaves[a]->mapping, 0, junk, sizeof junk);
    }
}

static void handle_request(const uint8_t *req, size_t len)
{
    unsigned addr = req[0];
    if (addr == 0) {
        handle_broadcast(req, len);
        return;
    }
    struct slave *s = slaves[addr];
    if (!s)
        return;

    /* Take a snapshot and consume one count first, so that the fault applies to
     * exactly COUNT requests whatever this one turns out to be. */
    struct fault f = s->fault;
    if (s->fault.kind != FAULT_NONE && s->fault.remaining > 0 && --s->fault.remaining == 0)
        s->fault.kind = FAULT_NONE;

    if (f.kind == FAULT_DROP || f.kind == FAULT_DEAD)
        return;
    if (f.kind == FAULT_LATE)
        sleep_ms(f.param);

    uint8_t rsp[MAX_FRAME + 1];
    uint8_t *body = rsp + 1; /* room for a stray byte in front */
    size_t n;
    unsigned exc = f.kind == FAULT_EXCEPTION ? f.param : precheck(req, len);
    if (exc)
        n = build_exception(req, exc, body);
    else
        n = capture_reply(req, (int)len, &s->mapping, 0, body, MAX_FRAME);
    if (n == 0)
        return;

    uint8_t *out = body;
    if (f.kind == FAULT_BADCRC)
        body[n - 1] ^= 0xFF;
    if (f.kind == FAULT_STRAY) {
        rsp[0] = 0x00;
        out = rsp;
        n++;
    }
    /* Logged before the write so that a test reading stdout never sees the
     * client react to bytes the log has not announced yet. */
    out_hex("tx", out, n);
    if (write_all(port_fd, out, n) < 0)
        fprintf(stderr, "%s: write to port failed: %s\n", prog, strerror(errno));
}

/* ---- Modbus TCP ---- */

/* Runs libmodbus's reply on a TCP request (the whole ADU, MBAP header first) with
 * ctx->s redirected to the capture socket pair. */
static size_t capture_tcp_reply(const uint8_t *adu, int adu_len, modbus_mapping_t *map,
                                int exception, uint8_t *rsp, size_t cap)
{
    modbus_set_socket(ctx, capture_wr);
    int rc = exception ? modbus_reply_exception(ctx, adu, (unsigned)exception)
                       : modbus_reply(ctx, adu, adu_len, map);
    modbus_set_socket(ctx, -1);
    if (rc < 0)
        fprintf(stderr, "%s: libmodbus reply failed: %s\n", prog, modbus_strerror(errno));
    return drain_capture(rsp, cap);
}

static size_t build_tcp_exception(const uint8_t *adu, unsigned code, uint8_t *rsp)
{
    if (code >= 1 && code < MODBUS_EXCEPTION_MAX)
        return capture_tcp_reply(adu, 0, NULL, (int)code, rsp, MAX_ADU);
    memcpy(rsp, adu, 4);
    rsp[4] = 0;
    rsp[5] = 3;
    rsp[6] = adu[6];
    rsp[7] = (uint8_t)(adu[7] | 0x80);
    rsp[8] = (uint8_t)code;
    return 9;
}

static void handle_tcp_request(int fd, const uint8_t *adu, size_t len)
{
    /* The unit id and PDU read like an RTU frame without its CRC: precheck() and
     * the test harness (which looks at the function code in 'rx') take them so. */
    const uint8_t *unit_pdu = adu + 6;
    size_t rtu_len = len - 6 + 2;
    unsigned unit = adu[6];
    out_hex("rx", unit_pdu, len - 6);
    frames_ok++;
    uint8_t rsp[MAX_ADU + 16];
    size_t n;
    if (unit == 0) {
        /* Passed on to the line as a broadcast: applied, never answered. */
        if ((adu[7] == MODBUS_FC_WRITE_SINGLE_REGISTER || adu[7] == MODBUS_FC_WRITE_MULTIPLE_REGISTERS)
            && precheck(unit_pdu, rtu_len) == 0) {
            for (int a = 1; a < MAX_SLAVES; a++)
                if (slaves[a])
                    capture_tcp_reply(adu, (int)len, &slaves[a]->mapping, 0, rsp, sizeof rsp);
        }
        return;
    }
    struct slave *s = slaves[unit];
    if (!s) {
        n = build_tcp_exception(adu, MODBUS_EXCEPTION_GATEWAY_TARGET, rsp);
    } else {
        struct fault f = s->fault;
        if (s->fault.kind != FAULT_NONE && s->fault.remaining > 0 && --s->fault.remaining == 0)
            s->fault.kind = FAULT_NONE;
        if (f.kind == FAULT_DROP || f.kind == FAULT_DEAD)
            return;
        if (f.kind == FAULT_LATE)
            sleep_ms(f.param);
        unsigned exc = f.kind == FAULT_EXCEPTION ? f.param : precheck(unit_pdu, rtu_len);
        n = exc ? build_tcp_exception(adu, exc, rsp)
                : capture_tcp_reply(adu, (int)len, &s->mapping, 0, rsp, sizeof rsp);
    }
    if (n == 0)
        return;
    out_hex("tx", rsp, n);
    if (write_all(fd, rsp, n) < 0)
        fprintf(stderr, "%s: write to client failed: %s\n", prog, strerror(errno));
}

static void drop_client(int i)
{
    close(clients[i]);
    clients[i] = -1;
    client_len[i] = 0;
}

static void read_client(int i)
{
    ssize_t n = read(clients[i], client_buf[i] + client_len[i], sizeof client_buf[i] - client_len[i]);
    if (n <= 0) {
        if (n < 0 && (errno == EAGAIN || errno == EINTR))
            return;
        drop_client(i);
        return;
    }
    client_len[i] += (size_t)n;
    while (client_len[i] >= 7) {
        const uint8_t *b = client_buf[i];
        size_t length = (size_t)(b[4] << 8 | b[5]);
        if (b[2] != 0 || b[3] != 0 || length < 2 || length > MAX_ADU - 6) {
            /* Not Modbus TCP: a gateway hangs up. */
            frames_bad++;
            out_hex("rxbad", b, client_len[i]);
            drop_client(i);
            return;
        }
        if (client_len[i] < 6 + length)
            return;
        handle_tcp_request(clients[i], b, 6 + length);
        memmove(client_buf[i], b + 6 + length, client_len[i] - 6 - length);
        client_len[i] -= 6 + length;
    }
}

static void accept_client(void)
{
    int fd = accept(listen_fd, NULL, NULL);
    if (fd < 0)
        return;
    for (int i = 0; i < MAX_CLIENTS; i++) {
        if (clients[i] < 0) {
            clients[i] = fd;
            client_len[i] = 0;
            return;
        }
    }
    close(fd);   /* as a gateway with all its connections taken */
}

/* Length of the request starting at buf[0]: >0 known, 0 = need more bytes to
 * tell, -1 = function without a fixed layout, ends at the next silence. */
static int expected_length(const uint8_t *buf, size_t len)
{
    if (len < 2)
        return 0;
    switch (buf[1]) {
    case MODBUS_FC_READ_HOLDING_REGISTERS:
    case MODBUS_FC_READ_INPUT_REGISTERS:
    case MODBUS_FC_WRITE_SINGLE_REGISTER:
        return 8;
    case MODBUS_FC_WRITE_MULTIPLE_REGISTERS:
        return len < 7 ? 0 : 9 + buf[6];
    default:
        return -1;
    }
}

static void complete_frame(const uint8_t *buf, size_t len)
{
    if (!crc_ok(buf, len)) {
        frames_bad++;
        out_hex("rxbad", buf, len);
        return;
    }
    frames_ok++;
    out_hex("rx", buf, len);
    handle_request(buf, len);
}

static uint8_t rxbuf[4096];
static size_t rxlen;

/* Cuts every frame whose length is known and complete off the front of the
 * receive buffer. A known length is trusted even when the CRC then fails: the
 * bad frame is reported exactly and the bytes after it get their own chance. */
static void parse_rx(void)
{
    for (;;) {
        int need = expected_length(rxbuf, rxlen);
        if (need <= 0 || rxlen < (size_t)need)
            return;
        complete_frame(rxbuf, (size_t)need);
        memmove(rxbuf, rxbuf + need, rxlen - (size_t)need);
        rxlen -= (size_t)need;
    }
}

/* Silence ends whatever is pending: a frame of unknown layout, or the remains
 * of a truncated one (which then fails its CRC and is reported as rxbad). */
static void flush_rx_on_silence(void)
{
    if (rxlen > 0)
        complete_frame(rxbuf, rxlen);
    rxlen = 0;
}

static int read_port(void)
{
    if (rxlen == sizeof rxbuf)
        flush_rx_on_silence();
    ssize_t n = read(port_fd, rxbuf + rxlen, sizeof rxbuf - rxlen);
    if (n > 0) {
        rxlen += (size_t)n;
        parse_rx();
        return 1;
    }
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR))
        return 0;
    /* EIO/EOF: the other end of the pty went away; nothing more can arrive. */
    fprintf(stderr, "%s: port closed: %s\n", prog, n == 0 ? "end of file" : strerror(errno));
    return -1;
}

/* ---- stdin commands ---- */

#define MAX_TOKENS 140

static struct slave *cmd_slave(const char *tok, const char **err)
{
    unsigned long a;
    if (parse_num(tok, 255, &a) < 0 || !slaves[a]) {
        *err = "unknown slave";
        return NULL;
    }
    return slaves[a];
}

static int opt_count(char **tok, int ntok, int idx, long *count, const char **err)
{
    *count = -1;
    if (idx < ntok) {
        unsigned long c;
        if (parse_num(tok[idx], 1000000000UL, &c) < 0 || c == 0) {
            *err = "bad COUNT";
            return -1;
        }
        *count = (long)c;
        idx++;
    }
    if (idx != ntok) {
        *err = "too many arguments";
        return -1;
    }
    return 0;
}

static const char *cmd_fault(char **tok, int ntok)
{
    const char *err = NULL;
    if (ntok < 3)
        return "usage: fault SLAVE MODE [ARGS]";
    struct slave *s = cmd_slave(tok[1], &err);
    if (!s)
        return err;
    const char *mode = tok[2];
    struct fault f = { FAULT_NONE, 0, -1 };
    unsigned long v;

    if (strcmp(mode, "none") == 0 || strcmp(mode, "dead") == 0) {
        if (ntok != 3)
            return "too many arguments";
        f.kind = mode[0] == 'n' ? FAULT_NONE : FAULT_DEAD;
    } else if (tcp_mode && (strcmp(mode, "stray") == 0 || strcmp(mode, "badcrc") == 0)) {
        return "no stray bytes or CRCs over Modbus TCP";
    } else if (strcmp(mode, "drop") == 0 || strcmp(mode, "stray") == 0
               || strcmp(mode, "badcrc") == 0) {
        f.kind = mode[0] == 'd' ? FAULT_DROP : mode[0] == 's' ? FAULT_STRAY : FAULT_BADCRC;
        if (opt_count(tok, ntok, 3, &f.remaining, &err) < 0)
            return err;
    } else if (strcmp(mode, "late") == 0) {
        if (ntok < 4 || parse_num(tok[3], 600000, &v) < 0)
            return "usage: fault SLAVE late MS [COUNT]";
        f.kind = FAULT_LATE;
        f.param = (unsigned)v;
        if (opt_count(tok, ntok, 4, &f.remaining, &err) < 0)
            return err;
    } else if (strcmp(mode, "exception") == 0) {
        if (ntok < 4 || parse_num(tok[3], 255, &v) < 0 || v == 0)
            return "usage: fault SLAVE exception CODE(1..255) [COUNT]";
        f.kind = FAULT_EXCEPTION;
        f.param = (unsigned)v;
        if (opt_count(tok, ntok, 4, &f.remaining, &err) < 0)
            return err;
    } else {
        return "unknown fault mode";
    }
    s->fault = f;
    return NULL;
}

static const char *cmd_set(char **tok, int ntok)
{
    const char *err = NULL;
    unsigned long addr, w;
    if (ntok < 4)
        return "usage: set SLAVE ADDR WORD [WORD...]";
    struct slave *s = cmd_slave(tok[1], &err);
    if (!s)
        return err;
    if (parse_num(tok[2], NUM_REGS - 1, &addr) < 0)
        return "bad ADDR";
    if (addr + (unsigned long)(ntok - 3) > NUM_REGS)
        return "words run past register 0xFFFF";
    /* Validate everything first so a typo does not leave half the words set. */
    for (int i = 3; i < ntok; i++)
        if (parse_num(tok[i], 0xFFFF, &w) < 0)
            return "bad WORD";
    for (int i = 3; i < ntok; i++) {
        parse_num(tok[i], 0xFFFF, &w);
        s->regs[addr + (unsigned long)(i - 3)] = (uint16_t)w;
    }
    return NULL;
}

static const char *cmd_get(char **tok, int ntok)
{
    const char *err = NULL;
    unsigned long addr, count = 1;
    if (ntok < 3 || ntok > 4)
        return "usage: get SLAVE ADDR [COUNT]";
    struct slave *s = cmd_slave(tok[1], &err);
    if (!s)
        return err;
    if (parse_num(tok[2], NUM_REGS - 1, &addr) < 0)
        return "bad ADDR";
    if (ntok == 4 && (parse_num(tok[3], 125, &count) < 0 || count == 0))
        return "bad COUNT (1..125)";
    if (addr + count > NUM_REGS)
        return "range runs past register 0xFFFF";
    fputs("regs", stdout);
    for (unsigned long i = 0; i < count; i++)
        fprintf(stdout, " %04X", s->regs[addr + i]);
    fputc('\n', stdout);
    fflush(stdout);
    return NULL;
}

/* Returns 1 when the peer should quit. */
static int run_command(char *line)
{
    char *tok[MAX_TOKENS];
    int ntok = 0;
    for (char *p = strtok(line, " \t\r"); p; p = strtok(NULL, " \t\r")) {
        if (ntok == MAX_TOKENS) {
            out_line("error: too many words");
            return 0;
        }
        tok[ntok++] = p;
    }
    if (ntok == 0 || tok[0][0] == '#')
        return 0;

    const char *err = NULL;
    int quit = 0;
    if (strcmp(tok[0], "fault") == 0)
        err = cmd_fault(tok, ntok);
    else if (strcmp(tok[0], "set") == 0)
        err = cmd_set(tok, ntok);
    else if (strcmp(tok[0], "get") == 0)
        err = cmd_get(tok, ntok);
    else if (strcmp(tok[0], "stats") == 0)
        out_line("stats rx=%lu rxbad=%lu", frames_ok, frames_bad);
    else if (strcmp(tok[0], "quit") == 0)
        quit = 1;
    else
        err = "unknown command";

    if (err)
        out_line("error: %s", err);
    else
        out_line("ok");
    return quit;
}

static char inbuf[8192];
static size_t inlen;

/* Returns 1 on quit or EOF. */
static int read_stdin(void)
{
    ssize_t n = read(STDIN_FILENO, inbuf + inlen, sizeof inbuf - 1 - inlen);
    if (n < 0)
        return (errno == EINTR || errno == EAGAIN) ? 0 : 1;
    if (n == 0) {
        /* A last command without newline still counts. */
        if (inlen > 0) {
            inbuf[inlen] = '\0';
            inlen = 0;
            run_command(inbuf);
        }
        return 1;
    }
    inlen += (size_t)n;
    for (;;) {
        char *nl = memchr(inbuf, '\n', inlen);
        if (!nl)
            break;
        *nl = '\0';
        size_t used = (size_t)(nl - inbuf) + 1;
        int quit = run_command(inbuf);
        memmove(inbuf, inbuf + used, inlen - used);
        inlen -= used;
        if (quit)
            return 1;
    }
    if (inlen == sizeof inbuf - 1) {
        out_line("error: line too long");
        inlen = 0;
    }
    return 0;
}

/* ---- start-up ---- */

static void apply_set_option(const char *arg)
{
    char buf[4096];
    if (strlen(arg) >= sizeof buf)
        die("--set argument too long");
    strcpy(buf, arg);
    char *colon = strchr(buf, ':');
    char *eq = colon ? strchr(colon + 1, '=') : NULL;
    if (!colon || !eq)
        die("--set expects SLAVE:ADDR=WORD[,WORD...], got '%s'", arg);
    *colon = '\0';
    *eq = '\0';
    unsigned long sl, addr, w;
    if (parse_num(buf, 255, &sl) < 0 || !slaves[sl])
        die("--set '%s': slave is not one given with --slave", arg);
    if (parse_num(colon + 1, NUM_REGS - 1, &addr) < 0)
        die("--set '%s': bad register address", arg);
    char *save = NULL;
    for (char *p = strtok_r(eq + 1, ",", &save); p; p = strtok_r(NULL, ",", &save)) {
        if (addr >= NUM_REGS)
            die("--set '%s': words run past register 0xFFFF", arg);
        if (parse_num(p, 0xFFFF, &w) < 0)
            die("--set '%s': bad word '%s'", arg, p);
        slaves[sl]->regs[addr++] = (uint16_t)w;
    }
}

static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
}

int main(int argc, char **argv)
{
    const char *port = NULL;
    long tcp_port = -1;
    unsigned long baud = 19200;
    char parity = 'N';
    int stop_bits = 1;
    const char *sets[256];
    int nsets = 0;

    static const struct option opts[] = {
        { "port", required_argument, NULL, 'p' },
        { "tcp", required_argument, NULL, 't' },
        { "baud", required_argument, NULL, 'b' },
        { "format", required_argument, NULL, 'f' },
        { "slave", required_argument, NULL, 's' },
        { "set", required_argument, NULL, 'S' },
        { "help", no_argument, NULL, 'h' },
        { NULL, 0, NULL, 0 },
    };
    int c;
    unsigned long v;
    while ((c = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        switch (c) {
        case 'p':
            port = optarg;
            break;
        case 't':
            if (parse_num(optarg, 65535, &v) < 0)
                die("bad --tcp '%s' (0..65535)", optarg);
            tcp_port = (long)v;
            tcp_mode = 1;
            break;
        case 'b':
            if (parse_num(optarg, 4000000, &baud) < 0 || baud == 0)
                die("bad --baud '%s'", optarg);
            break;
        case 'f':
            if (strlen(optarg) != 3 || optarg[0] != '8' || !strchr("NEO", optarg[1])
                || (optarg[2] != '1' && optarg[2] != '2'))
                die("bad --format '%s' (expected 8N1, 8E1, 8O1 or 8N2)", optarg);
            parity = optarg[1];
            stop_bits = optarg[2] - '0';
            break;
        case 's':
            if (parse_num(optarg, 247, &v) < 0 || v == 0)
                die("bad --slave '%s' (1..247)", optarg);
            add_slave((unsigned)v);
            break;
        case 'S':
            if (nsets == (int)(sizeof sets / sizeof sets[0]))
                die("too many --set options");
            sets[nsets++] = optarg;
            break;
        case 'h':
            usage(stdout);
            return 0;
        default:
            usage(stderr);
            return 1;
        }
    }
    if (optind < argc)
        die("unexpected argument '%s'", argv[optind]);
    if (!port == !tcp_mode)
        die("give either --port or --tcp");
    int have_slave = 0;
    for (int a = 1; a < MAX_SLAVES; a++)
        have_slave |= slaves[a] != NULL;
    if (!have_slave)
        die("at least one --slave is required");
    /* --set is applied after all options so that it may precede its --slave. */
    for (int i = 0; i < nsets; i++)
        apply_set_option(sets[i]);

    /* A socket pair rather than a pipe: the TCP backend send()s its replies. */
    int pipefd[2];
    if (socketpair(AF_UNIX, SOCK_STREAM, 0, pipefd) < 0)
        die("socketpair: %s", strerror(errno));
    capture_rd = pipefd[0];
    capture_wr = pipefd[1];
    fcntl(capture_rd, F_SETFL, fcntl(capture_rd, F_GETFL) | O_NONBLOCK);

    for (int i = 0; i < MAX_CLIENTS; i++)
        clients[i] = -1;
    if (tcp_mode) {
        ctx = modbus_new_tcp("127.0.0.1", (int)tcp_port);
        if (!ctx)
            die("cannot create TCP context: %s", modbus_strerror(errno));
        listen_fd = modbus_tcp_listen(ctx, MAX_CLIENTS);
        if (listen_fd < 0) {
            int e = errno;
            modbus_free(ctx);
            die("cannot listen on 127.0.0.1:%ld: %s", tcp_port, modbus_strerror(e));
        }
        struct sockaddr_in bound;
        socklen_t bound_len = sizeof bound;
        if (getsockname(listen_fd, (struct sockaddr *)&bound, &bound_len) < 0)
            die("getsockname: %s", strerror(errno));
        out_line("listening %u", (unsigned)ntohs(bound.sin_port));
    } else {
        ctx = modbus_new_rtu(port, (int)baud, parity, 8, stop_bits);
        if (!ctx)
            die("cannot create RTU context for %s: %s", port, modbus_strerror(errno));
        if (modbus_connect(ctx) < 0) {
            int e = errno;
            modbus_free(ctx);
            die("cannot open %s at %lu baud: %s", port, baud, modbus_strerror(e));
        }
        port_fd = modbus_get_socket(ctx);
    }

    /* SIGTERM/SIGINT stay blocked except inside pselect(), so a signal can
     * neither be lost between the flag check and the wait nor cut a reply in
     * half. SIGPIPE is ignored so a vanished test harness shows up as EOF on
     * stdin instead of killing the peer mid-write. */
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGINT, &sa, NULL);
    signal(SIGPIPE, SIG_IGN);
    sigset_t block, waitmask;
    sigemptyset(&block);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGINT);
    sigprocmask(SIG_BLOCK, &block, &waitmask);
    sigdelset(&waitmask, SIGTERM);
    sigdelset(&waitmask, SIGINT);

    out_line("ready");

    int rc = 0;
    int64_t last_rx = 0;
    while (!stop_requested) {
        fd_set rfds;
        FD_ZERO(&rfds);
        FD_SET(STDIN_FILENO, &rfds);
        int maxfd = STDIN_FILENO;
        if (tcp_mode) {
            FD_SET(listen_fd, &rfds);
            maxfd = listen_fd > maxfd ? listen_fd : maxfd;
            for (int i = 0; i < MAX_CLIENTS; i++) {
                if (clients[i] >= 0) {
                    FD_SET(clients[i], &rfds);
                    maxfd = clients[i] > maxfd ? clients[i] : maxfd;
                }
            }
        } else {
            FD_SET(port_fd, &rfds);
            maxfd = port_fd > maxfd ? port_fd : maxfd;
        }

        struct timespec ts, *tsp = NULL;
        if (rxlen > 0) {
            int64_t left = last_rx + FRAME_GAP_MS - now_ms();
            if (left < 0)
                left = 0;
            ts.tv_sec = (time_t)(left / 1000);
            ts.tv_nsec = (long)(left % 1000) * 1000000L;
            tsp = &ts;
        }
        int n = pselect(maxfd + 1, &rfds, NULL, NULL, tsp, &waitmask);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            fprintf(stderr, "%s: select: %s\n", prog, strerror(errno));
            rc = 1;
            break;
        }
        if (tcp_mode && n > 0) {
            for (int i = 0; i < MAX_CLIENTS; i++)
                if (clients[i] >= 0 && FD_ISSET(clients[i], &rfds))
                    read_client(i);
            if (FD_ISSET(listen_fd, &rfds))
                accept_client();
        }
        if (!tcp_mode && n > 0 && FD_ISSET(port_fd, &rfds)) {
            int r = read_port();
            if (r < 0) {
                rc = 1;
                break;
            }
            if (r > 0)
                last_rx = now_ms();
        }
        if (rxlen > 0 && now_ms() - last_rx >= FRAME_GAP_MS)
            flush_rx_on_silence();
        if (n > 0 && FD_ISSET(STDIN_FILENO, &rfds) && read_stdin())
            break;
    }

    if (frames_bad > 0)
        fprintf(stderr, "%s: %lu frame(s) dropped for bad CRC, %lu good\n", prog, frames_bad,
                frames_ok);
    for (int i = 0; i < MAX_CLIENTS; i++)
        if (clients[i] >= 0)
            close(clients[i]);
    if (listen_fd >= 0)
        close(listen_fd);
    if (!tcp_mode)
        modbus_close(ctx);
    modbus_free(ctx);
    close(capture_rd);
    close(capture_wr);
    for (int a = 0; a < MAX_SLAVES; a++) {
        if (slaves[a]) {
            free(slaves[a]->regs);
            free(slaves[a]);
        }
    }
    return rc;
}
