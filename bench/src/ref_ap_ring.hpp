/* SPDX-License-Identifier: Apache-2.0 */
/**
 * @file ref_ap_ring.hpp
 * @brief Bench peer: a ByteBuffer / ObjectBuffer in the style of ArduPilot's
 *        AP_HAL/utility/RingBuffer, written for this project from the algorithm
 *        description in shared/reference/performance.md §1.2 and
 *        ardupilot.md §1.4. It is NOT ArduPilot code.
 *
 * What it reproduces (the parts that decide the cost):
 * - head (read index) and tail (write index) are std::atomic<uint32_t> used
 *   with the default seq_cst ordering; no cache-line separation; no cached
 *   copy of the other side's index.
 * - one byte of the storage always stays empty (usable = size - 1); an
 *   ObjectBuffer<T>(n) allocates n * sizeof(T) + 1 bytes (not a power of two).
 * - every index advance is `% size`.
 * - write() = reserve() (which calls space()) + memcpy of up to two segments
 *   + commit(), and commit() calls space() again; read() = peekbytes()
 *   (available() + memcpy) + advance() (available() again).
 * - ObjectBuffer::push() checks space() first, then write(); pop() checks
 *   available() first, then read().
 */
#ifndef REF_AP_RING_HPP
#define REF_AP_RING_HPP

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace apref {

class ByteBuffer {
public:
    struct IoVec {
        uint8_t *data;
        uint32_t len;
    };

    explicit ByteBuffer(uint32_t size_) : buf(static_cast<uint8_t *>(std::calloc(size_, 1))), size(size_) {}
    ~ByteBuffer() { std::free(buf); }
    ByteBuffer(const ByteBuffer &) = delete;
    ByteBuffer &operator=(const ByteBuffer &) = delete;

    /* consumer: bytes readable (tail copied once) */
    uint32_t available() const
    {
        const uint32_t t = tail;
        const uint32_t h = head;
        return (t >= h) ? (t - h) : (size - h + t);
    }

    /* producer: bytes writable (head copied once), one byte kept empty */
    uint32_t space() const
    {
        const uint32_t h = head;
        const uint32_t t = tail;
        const uint32_t used = (t >= h) ? (t - h) : (size - h + t);
        return size - 1u - used;
    }

    uint32_t reserve(IoVec vec[2], uint32_t len)
    {
        const uint32_t sp = space();
        if (len > sp) {
            len = sp;
        }
        if (len == 0u) {
            return 0u;
        }
        const uint32_t t = tail;
        vec[0].data = &buf[t];
        const uint32_t first = size - t;
        if (first >= len) {
            vec[0].len = len;
            return 1u;
        }
        vec[0].len = first;
        vec[1].data = buf;
        vec[1].len = len - first;
        return 2u;
    }

    bool commit(uint32_t len)
    {
        if (len > space()) {
            return false;
        }
        tail = (tail + len) % size;
        return true;
    }

    uint32_t write(const uint8_t *data, uint32_t len)
    {
        IoVec vec[2];
        const uint32_t n = reserve(vec, len);
        uint32_t ret = 0u;
        for (uint32_t i = 0u; i < n; i++) {
            std::memcpy(vec[i].data, data + ret, vec[i].len);
            ret += vec[i].len;
        }
        commit(ret);
        return ret;
    }

    uint32_t peekbytes(uint8_t *data, uint32_t len) const
    {
        const uint32_t avail = available();
        if (len > avail) {
            len = avail;
        }
        if (len == 0u) {
            return 0u;
        }
        const uint32_t h = head;
        const uint32_t first = size - h;
        if (first >= len) {
            std::memcpy(data, &buf[h], len);
        } else {
            std::memcpy(data, &buf[h], first);
            std::memcpy(data + first, buf, len - first);
        }
        return len;
    }

    bool advance(uint32_t n)
    {
        if (n > available()) {
            return false;
        }
        head = (head + n) % size;
        return true;
    }

    uint32_t read(uint8_t *data, uint32_t len)
    {
        const uint32_t n = peekbytes(data, len);
        advance(n);
        return n;
    }

private:
    uint8_t *buf;
    uint32_t size;
    std::atomic<uint32_t> head{0};
    std::atomic<uint32_t> tail{0};
};

template <typename T> class ObjectBuffer {
public:
    explicit ObjectBuffer(uint32_t n) : buffer(n * static_cast<uint32_t>(sizeof(T)) + 1u) {}

    uint32_t available() const { return buffer.available() / static_cast<uint32_t>(sizeof(T)); }
    uint32_t space() const { return buffer.space() / static_cast<uint32_t>(sizeof(T)); }

    bool push(const T &obj)
    {
        if (buffer.space() < sizeof(T)) {
            return false;
        }
        return buffer.write(reinterpret_cast<const uint8_t *>(&obj), sizeof(T)) == sizeof(T);
    }

    bool pop(T &obj)
    {
        if (available() == 0u) {
            return false;
        }
        return buffer.read(reinterpret_cast<uint8_t *>(&obj), sizeof(T)) == sizeof(T);
    }

private:
    ByteBuffer buffer;
};

} // namespace apref

#endif /* REF_AP_RING_HPP */
