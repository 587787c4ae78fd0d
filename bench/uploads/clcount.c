// An LD_PRELOAD shim that records every clCreateBuffer and clEnqueueWriteBuffer a program makes:
// the bytes, and an FNV-1a hash of the host data copied in (0 where none), so that the same
// array uploaded twice shows as two records of the same size and hash. At exit it writes one
// line per call to the file CLCOUNT_OUT names: "create|write SIZE HASH". A process that made no
// such call writes nothing (a shell or a timeout wrapper inherits LD_PRELOAD too).
// Built and run by bench/uploads/count_uploads.py.
#define _GNU_SOURCE
#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct {
    int write;
    size_t size;
    unsigned long long hash;
} Record;

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static Record* records;
static size_t count, capacity;

static unsigned long long fnv1a(const void* data, size_t size) {
    const unsigned char* b = (const unsigned char*)data;
    unsigned long long h = 1469598103934665603ULL;
    for (size_t i = 0; i < size; ++i) h = (h ^ b[i]) * 1099511628211ULL;
    return h;
}

static void keep(int write, size_t size, const void* data) {
    const unsigned long long hash = data ? fnv1a(data, size) : 0ULL;
    pthread_mutex_lock(&lock);
    if (count == capacity) {
        capacity = capacity ? 2 * capacity : 1024;
        records = realloc(records, capacity * sizeof(Record));
    }
    records[count++] = (Record){write, size, hash};
    pthread_mutex_unlock(&lock);
}

CL_API_ENTRY cl_mem CL_API_CALL clCreateBuffer(cl_context context, cl_mem_flags flags, size_t size, void* host,
                                               cl_int* error) {
    typedef cl_mem (*Create)(cl_context, cl_mem_flags, size_t, void*, cl_int*);
    static Create real;
    if (!real) real = (Create)dlsym(RTLD_NEXT, "clCreateBuffer");
    keep(0, size, (flags & (CL_MEM_COPY_HOST_PTR | CL_MEM_USE_HOST_PTR)) ? host : NULL);
    return real(context, flags, size, host, error);
}

CL_API_ENTRY cl_int CL_API_CALL clEnqueueWriteBuffer(cl_command_queue queue, cl_mem buffer, cl_bool blocking,
                                                     size_t offset, size_t size, const void* data, cl_uint waits,
                                                     const cl_event* waitList, cl_event* event) {
    typedef cl_int (*Write)(cl_command_queue, cl_mem, cl_bool, size_t, size_t, const void*, cl_uint,
                            const cl_event*, cl_event*);
    static Write real;
    if (!real) real = (Write)dlsym(RTLD_NEXT, "clEnqueueWriteBuffer");
    keep(1, size, data);
    return real(queue, buffer, blocking, offset, size, data, waits, waitList, event);
}

__attribute__((destructor)) static void report(void) {
    const char* path = getenv("CLCOUNT_OUT");
    if (count == 0 || !path) return;
    FILE* out = fopen(path, "w");
    if (!out) return;
    for (size_t i = 0; i < count; ++i)
        fprintf(out, "%s %zu %016llx\n", records[i].write ? "write" : "create", records[i].size, records[i].hash);
    fclose(out);
}
