/*
 * ros_loopback: make roscpp nodes listen on loopback only when ROS is bound to this machine.
 *
 * Why: with ROS_HOSTNAME=localhost (or ROS_IP=127.x / ::1) rospy and the XML-RPC servers bind to the
 * loopback address, but roscpp's TCPROS server (TransportTCP::listen) always binds INADDR_ANY and only
 * refuses remote peers after accepting them. So rosout (part of roscore) and every C++ node keep a port
 * open on every network interface. Preloaded by scripts/env.sh, this bind() wrapper rewrites a wildcard
 * address to the loopback address, in roscpp processes only, and only when ROS is bound to localhost;
 * every other bind() is passed through unchanged.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <link.h>
#include <netinet/in.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>

static int ros_bound_to_loopback(void)
{
    const char *hostname = getenv("ROS_HOSTNAME");
    const char *ip = getenv("ROS_IP");

    if (hostname && *hostname)  /* ROS_HOSTNAME wins over ROS_IP, as in ROS itself */
        return strcmp(hostname, "localhost") == 0 || strncmp(hostname, "127.", 4) == 0;
    return ip && (strcmp(ip, "localhost") == 0 || strncmp(ip, "127.", 4) == 0 || strcmp(ip, "::1") == 0);
}

static int find_roscpp(struct dl_phdr_info *info, size_t size, void *unused)
{
    (void)size;
    (void)unused;
    return info->dlpi_name && strstr(info->dlpi_name, "/libroscpp.so") != NULL;
}

static int is_roscpp_process(void)
{
    return dl_iterate_phdr(find_roscpp, NULL) != 0;
}

int bind(int fd, const struct sockaddr *address, socklen_t length)
{
    static int (*real_bind)(int, const struct sockaddr *, socklen_t);

    if (!real_bind)
        real_bind = (int (*)(int, const struct sockaddr *, socklen_t))dlsym(RTLD_NEXT, "bind");
    if (address && ros_bound_to_loopback() && is_roscpp_process()) {
        if (address->sa_family == AF_INET && length >= sizeof(struct sockaddr_in)) {
            struct sockaddr_in local;
            memcpy(&local, address, sizeof local);
            if (local.sin_addr.s_addr == htonl(INADDR_ANY)) {
                local.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
                return real_bind(fd, (const struct sockaddr *)&local, sizeof local);
            }
        } else if (address->sa_family == AF_INET6 && length >= sizeof(struct sockaddr_in6)) {
            struct sockaddr_in6 local;
            memcpy(&local, address, sizeof local);
            if (memcmp(&local.sin6_addr, &in6addr_any, sizeof in6addr_any) == 0) {
                local.sin6_addr = in6addr_loopback;
                return real_bind(fd, (const struct sockaddr *)&local, sizeof local);
            }
        }
    }
    return real_bind(fd, address, length);
}
